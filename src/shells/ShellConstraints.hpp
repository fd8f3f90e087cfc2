// Prescribed generalized values of shells (clamped, simply supported and symmetry edges), by one
// of the solids' three methods per support (docs/shells.md, "Essential conditions").
//
// The transformation method in its collocation form (Chen, Pan, Wu & Liu 1996) with the boundary
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
//
// Nitsche and penalty (small rotations; shells/ShellWeakEdges.cpp): no rows are replaced; the
// held edges add boundary integrals to every row, with the jump j_c = u^h_c(X_e) - g_c(X_e):
//   nitsche  - integral phi_I T_c(d) - integral T_c(phi_I e_k) j_c + beta_c integral phi_I j_c
//              (Nitsche 1971; symmetric and consistent: the patch tests hold to round-off),
//   penalty  beta_c integral phi_I j_c only (symmetric, not consistent: errors fall like
//              1 / alpha),
// beta_c = alpha s_c / h with s_c the section's A_11 (translations) or D_11 (rotations) and h the
// particle spacing at the edge point: the solids' beta = alpha E / h for a section (alpha default
// 100 for nitsche, 1e4 for penalty). Explicit stages apply these terms as forces (their
// stiffness in the stable step), implicit ones add them to the residual and the tangent.
#pragma once

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "operators/CouplingGraph.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellBoundary.hpp"
#include "shells/ShellMetric.hpp"

namespace efg {

/// The value of one component along a node set, as a function of the reference position.
using ShellValue = std::function<double(const double* x)>;

/// How a support holds its components (the scene's boundary_conditions[].method).
enum class ShellMethod { transformation, penalty, nitsche };

struct ShellSupport {
  std::string node_set;
  /// u, v, w, theta_x, theta_y held on the set (an empty function: the component is free).
  std::array<ShellValue, shell_dofs_per_node> value;
  ShellMethod method = ShellMethod::transformation;
  /// nitsche and penalty: alpha of beta_c = alpha s_c / h (0: 100 for nitsche, 1e4 for penalty)
  double alpha = 0;
  /// where the scene gives it (e.g. "boundary_conditions[1]"), for messages; may be empty
  std::string key;
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

  /// A support held by nitsche or penalty (on any rank).
  bool weak() const { return weak_; }
  /// The values g_c(X_e) of the nitsche and penalty supports' edge points from `supports` (the
  /// same conditions at another time or load level).
  void set_edge_values(const std::vector<ShellSupport>& supports);
  /// r = the nitsche and penalty edge terms alone at d (owned dofs, overwritten): explicit
  /// stages apply -r as the supports' force. With `support_forces`: that force summed per
  /// support and component over every rank (5 per support, the constructor's order;
  /// collective): sum_I -r_(I,c), the total force (rotations: moment) a support applies.
  void weak_resistance(const FlatShellOperator::Vector& d_owned, FlatShellOperator::Vector& r_owned,
                       std::vector<double>* support_forces = nullptr) const;
  /// The energy of the nitsche and penalty terms at d, sum over the edge points of
  /// l sum_c (-T_c(d) j_c + beta_c j_c^2 / 2) (penalty: the second term), summed over every rank
  /// (collective): for elastic sections the potential whose gradient is weak_resistance, so
  /// strain energy + this is the potential of the shell on its supports. Nitsche is coercive
  /// only for beta above the trace inverse estimate: with beta too small that potential is
  /// unbounded below, and an explicit stage watches it turn negative (ShellExplicitStage).
  double weak_energy(const FlatShellOperator::Vector& d_owned) const;
  /// Replaces the rows of this rank's constrained dofs by their collocation rows (modify mode).
  /// The row scales are taken from the first matrix and kept (Newton's residual uses them).
  void replace_rows(FlatShellOperator::Matrix& K) const;
  /// (after replace_rows, whose row scales it uses)
  /// rhs(J, c) = s_c g_c(X_J) on this rank's constrained dofs, and the nitsche and penalty
  /// edges' loads -r_edges(0) (their terms in g) added to the others (a linear solve's right-hand
  /// side).
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
    double thickness = 0;         ///< sum phi_a t_a at the point
    double* committed = nullptr;  ///< J2 parts: the layers' committed states (op's store)
    std::size_t trial = 0;        ///< offset of its trial states in trial_
    /// finite rotations on a curved reference: the strains of the reference state and their
    /// metric (the reactions are per unit mesh length, shells/ShellMetric.hpp)
    std::array<double, shell_strains> reference{};
    ShellMetric metric;
    ShellMethod method = ShellMethod::transformation;
    int support = 0;  ///< index into the constructor's supports
    /// nitsche and penalty: beta_c per unit length, and the prescribed values g_c(X_e)
    std::array<double, shell_dofs_per_node> beta{}, g{};
  };
  using ReadView = decltype(std::declval<const FlatShellOperator::Vector&>().getLocalViewHost(
      Tpetra::Access::ReadOnly));
  using WriteView = decltype(std::declval<FlatShellOperator::Vector&>().getLocalViewHost(
      Tpetra::Access::ReadWrite));
  /// Small rotations: the edge point's traction T_c(d) (edge_traction of its resultants) and its
  /// rows, rows[c * width + k] = dT_c / dd_k over the point's dofs k = a * 5 + component (the
  /// section's tangent: exact for elastic parts).
  void linear_traction(const Edge& e, const ReadView& d, double (&T)[shell_dofs_per_node],
                       std::vector<double>& rows) const;
  /// A weak edge point's traction and its rows (linear_traction; nitsche only).
  struct WeakTraction {
    double T[shell_dofs_per_node] = {};
    std::vector<double> rows;
    bool nitsche = false;
  };
  WeakTraction weak_traction(const Edge& e, const ReadView& d) const;
  /// The jump j_c = sum_a phi_a d_(a,c) - g_c of a weak edge point.
  double jump(const Edge& e, const ReadView& d, std::size_t c) const;
  /// The nitsche or penalty terms of a weak edge point into f (overlap) and their derivative
  /// into K (shells/ShellWeakEdges.cpp).
  void add_weak_forces(const Edge& e, const ReadView& d, WriteView& f) const;
  void add_weak_terms(const Edge& e, const ReadView& d, FlatShellOperator::Matrix& K) const;
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
  std::size_t supports_ = 0;           ///< how many the constructor was given
  bool weak_ = false;                  ///< a support is held by nitsche or penalty
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
