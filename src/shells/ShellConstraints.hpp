// Prescribed generalized values of shells (clamped, simply supported and symmetry edges) by the
// transformation method in its collocation form (Chen, Pan, Wu & Liu 1996) with the boundary
// traction term of Wagner & Liu (2000):
//
// - with non-interpolating MLS shape functions a particle's dof is not the field's value there,
//   so the equation row of each constrained dof (J, c) is replaced by the collocation row
//     s_c sum_I phi_I(X_J) d_(I,c) = s_c g_c(X_J),
//   which makes the physical value exactly g_c at every particle of the node set; s_c (the
//   section's A_11 for translations, D_11 for rotations) puts the rows on the scale of the
//   stiffness rows they replace and does not change the solution;
// - the test functions phi_I of the remaining rows do not vanish on the constrained edges, so
//   those rows keep the edge work of the unknown reaction, - integral phi_I T_c(d) ds, with the
//   edge tractions of component c computed from the resultants (N n, Q . n, M n; see
//   edge_traction). Without it the method is not consistent: a constant-bending state would not
//   solve the discrete equations (the patch tests fail).
#pragma once

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "operators/CouplingGraph.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellBoundary.hpp"
#include "shells/ShellMetric.hpp"

namespace efg {

/// The value of one component along a node set, as a function of the reference position.
using ShellValue = std::function<double(const double* x)>;

struct ShellSupport {
  std::string node_set;
  /// u, v, w, theta_x, theta_y held on the set (an empty function: the component is free).
  std::array<ShellValue, shell_dofs_per_node> value;
};

class ShellConstraints {
 public:
  /// Throws InputError naming the scene file and the node set when a set is missing or covers
  /// no edge of a shell part.
  ShellConstraints(const Model& model, const FlatShellOperator& op,
                   const std::vector<ShellSupport>& supports);

  /// The couplings of the edge terms and of the collocation rows.
  void add_couplings(CouplingGraph& graph) const;
  /// Adds the derivative of the edge traction terms at the overlap values d (assembly mode;
  /// overlap rows). J2 parts: the edge points' own layers (their trial states written).
  void add_edge_terms(const FlatShellOperator::Vector& d_overlap,
                      FlatShellOperator::Matrix& K) const;
  /// f_(I,c) += - sum_e l_e phi_I(X_e) T_c(d) over the edge points, held components c (overlap).
  void add_edge_forces(const FlatShellOperator::Vector& d_overlap,
                       FlatShellOperator::Vector& f_overlap) const;
  /// The edge points' J2 states of the last evaluation become the committed ones.
  void commit() const;
  /// Replaces the rows of this rank's constrained dofs by their collocation rows (modify mode).
  /// The row scales are taken from the first matrix and kept (Newton's residual uses them).
  void replace_rows(FlatShellOperator::Matrix& K) const;
  /// (after replace_rows, whose row scales it uses)
  /// rhs(J, c) = s_c g_c(X_J) on this rank's constrained dofs (other entries untouched).
  void set_values(FlatShellOperator::Vector& rhs_owned) const;
  /// r(J, c) = s_c (sum_I phi_I(X_J) d_(I,c) - g) on this rank's constrained dofs, g from
  /// `values` (collocation_values' order); other entries untouched.
  void constrained_residual(const FlatShellOperator::Vector& d_overlap,
                            const std::vector<double>& values,
                            FlatShellOperator::Vector& r_owned) const;
  /// Zeroes the constrained dofs' entries of an owned vector.
  void zero_constrained(FlatShellOperator::Vector& v_owned) const;

  /// The collocation rows unscaled, C d = g with C_(J,c),(I,c) = phi_I(X_J): a row map of this
  /// rank's constrained dofs (in order), the owned dofs as domain, fill complete; `values` gets
  /// g_c(X_J) in the rows' order (explicit stages: shells/ShellMultipliers).
  Teuchos::RCP<Tpetra::CrsMatrix<>> collocation_matrix(std::vector<double>& values) const;
  /// g_c(X_J) of the same rows from `supports` (the same conditions, e.g. at another time).
  std::vector<double> collocation_values(const std::vector<ShellSupport>& supports) const;
  /// The support (index into the constructor's list) and component of each row, in order.
  std::vector<std::pair<int, int>> row_supports() const;

 private:
  struct Row {
    int node = 0, component = 0;  ///< owned (= overlap) node index of J, component c
    int support = 0;              ///< the support whose value it holds
    std::array<double, 2> x{};    ///< X_J
    double scale = 1, value = 0;
    std::vector<int> columns;  ///< overlap node indices of the particles reaching X_J
    std::vector<double> phi;   ///< phi_I(X_J)
  };
  struct Edge {
    ShellEdgePoint point;
    std::vector<int> node;  ///< overlap node indices of point.node
    std::array<bool, shell_dofs_per_node> held{};
    double* committed = nullptr;  ///< J2 parts: the layers' committed states (op's store)
    std::size_t trial = 0;        ///< offset of its trial states in trial_
    /// finite rotations on a curved reference: the strains of the reference state and their
    /// metric (the reactions are per unit mesh length, shells/ShellMetric.hpp)
    std::array<double, shell_strains> reference{};
    ShellMetric metric;
  };
  /// The resultants conjugate to the mesh-coordinate strains per unit mesh area (curved
  /// references; R itself otherwise).
  void to_mesh(const Edge& e, const double* R, double (&out)[shell_strains]) const;
  /// The edge point's strains at d, its resultants R and (when asked) their tangent S.
  /// With finite rotations (FlatShellOperator::finite_rotations) `fe` gets the point's
  /// kinematics (required then).
  template <class View>
  void edge_response(const Edge& e, const View& d, double (&R)[shell_strains], SectionTangent* S,
                     FiniteRotationPoint* fe = nullptr) const;
  template <class View>
  void edge_kinematics(const Edge& e, const View& d, FiniteRotationPoint& fe) const;
  /// The finite-rotation edge term's force -l phi_I T_c and its derivative (shells/
  /// FiniteRotation.hpp, finite_rotation_edge_reaction): T = t for translations, m . dd_I/dw
  /// for the rotation dofs of particle I.
  template <class View>
  void add_finite_edge_terms(const Edge& e, const View& d, FlatShellOperator::Matrix& K) const;
  template <class View, class Force>
  void add_finite_edge_forces(const Edge& e, const View& d, Force& f) const;

  const FlatShellOperator& op_;
  mutable std::vector<Row> rows_;      ///< this rank's (replace_rows sets the scales)
  mutable bool scaled_ = false;        ///< the row scales are set
  std::vector<Edge> edges_;            ///< this rank's
  mutable std::vector<double> trial_;  ///< the J2 edge points' trial states
};

/// The edge tractions conjugate to (u, v, w, theta_x, theta_y) from the resultants
/// R = (N_xx, N_yy, N_xy, M_xx, M_yy, M_xy, Q_x, Q_y) on an edge of outward normal n:
/// (N n)_x, (N n)_y, Q . n, -(M n)_y, (M n)_x (the rotation theta_x turns the normal by -y).
inline void edge_traction(const double (&R)[shell_strains], const std::array<double, 2>& n,
                          double (&T)[shell_dofs_per_node]) {
  T[shell_u] = R[0] * n[0] + R[2] * n[1];
  T[shell_v] = R[2] * n[0] + R[1] * n[1];
  T[shell_w] = R[6] * n[0] + R[7] * n[1];
  T[shell_rx] = -(R[5] * n[0] + R[4] * n[1]);
  T[shell_ry] = R[3] * n[0] + R[5] * n[1];
}

}  // namespace efg
