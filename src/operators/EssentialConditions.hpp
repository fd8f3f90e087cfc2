// Prescribed displacements with non-interpolating shape functions: the physical displacement at
// X is u^h(X) = sum_I phi_I(X) d_I, so u^h = u_bar cannot be imposed on the d_I directly.
// Three methods, chosen per condition (docs/boundary_conditions.md):
//
//  transformation - the kinematic constraint is collocated at the condition's nodes: the
//    equation of each constrained dof (J, i) is replaced by s (u^h_i(X_J) - u_bar_i(X_J)) = 0
//    (the boundary transformation of Chen & Wang 2000 in collocation form, scaled by
//    s = E h^(d-2) to match the stiffness rows), and the remaining equations get the boundary
//    traction term -integral over Gamma_u of phi_I (P n)_i, without which test functions that
//    do not vanish on Gamma_u break consistency (Wagner & Liu 2000). Exact nodal values;
//    nonsymmetric system.
//  nitsche - symmetric Nitsche (Nitsche 1971; Fernandez-Mendez & Huerta 2004):
//    - integral phi_I (P n)_i - integral (dP(phi_I e_i) n).(u^h - u_bar) + beta integral phi_I (u^h - u_bar)_i,
//    beta = alpha E / h (alpha default 100). Consistent and symmetric.
//  penalty - beta integral phi_I (u^h - u_bar)_i only (alpha default 1e4): symmetric, simple,
//    but not consistent: the error decreases like 1/alpha.
//
// Boundary integrals run over the sides of the part whose nodes all lie in the condition's node
// set, with the SCNI boundary points (operators/SideQuadrature). The reaction of a condition is
// the sum of the out-of-balance forces f_int - f_ext of the particles its boundary reaches, each
// particle's share of each component split among the conditions constraining that component by
// the weight of its shape function on their boundaries (so the reactions of all conditions
// balance the applied loads exactly).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "model/Curves.hpp"
#include "model/ExactSolutions.hpp"
#include "operators/BoundaryCellPressure.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

class EssentialConditions {
 public:
  /// Which displacement conditions to build: all (implicit stages), or only those enforced
  /// weakly by boundary integrals, nitsche and penalty (explicit stages, drivers/WeakSupports);
  /// of those, the ones active in `stage` ("": every condition, whatever its stages).
  /// transformation_only: the explicit stages' tracking of the transformation conditions'
  /// boundary-point history (drivers/WeakSupports), which they do not otherwise evaluate.
  /// explicit_forces: every condition's boundary points, no collocated rows (explicit stages
  /// with transformation_traction: the transformation's traction term as a force).
  enum class Selection { all, weak_only, transformation_only, explicit_forces };
  EssentialConditions(const Model& model, const SolidOperator& op, const ExactSolution* exact,
                      Selection selection = Selection::all, const std::string& stage = "");

  /// Couplings the constraint rows and boundary integrals add to the stiffness graph.
  void add_couplings(CouplingGraph& graph) const;

  /// Prescribed values at the current time: value x factor(curve).
  void set_factor(const LoadFactor& factor);

  /// Boundary integral terms into an overlap residual / a matrix in assembly mode. With
  /// `totals` (one entry per condition), also the sum of each condition's terms over this
  /// rank's boundary points.
  void add_boundary_terms(const Vector& d_overlap, Vector& r_overlap,
                          std::vector<std::array<double, 3>>* totals = nullptr) const;
  /// `bulk`: a mixed part's cell pressure in the traction term at kappa or at the bulk split's
  /// kappa_0 (operators/BulkTangent.hpp).
  void add_boundary_terms(const Vector& d_overlap, FEMatrix& K,
                          BulkTangent bulk = BulkTangent::full) const;
  /// The boundary points' tangents at d, kept for the products below (the stable-step estimate
  /// applies them a few hundred times at one d; evaluating them each time cost 17x the
  /// estimate's internal forces on a 10^3 block with three symmetry planes).
  struct BoundaryTangent;
  std::shared_ptr<const BoundaryTangent> boundary_tangent(const Vector& d_overlap) const;
  /// y += K_b(d) x: the matrix of add_boundary_terms(d, K) applied to x without forming it (the
  /// explicit stable-step estimate; transformation points with their traction term's
  /// symmetric part). Symmetric by construction: the consistency and symmetric terms use one
  /// tangent, so the product is exactly symmetric where differences of the nonlinear terms
  /// would not be.
  void apply_boundary_stiffness(const BoundaryTangent& tangent, const Vector& x_overlap,
                                Vector& y_overlap) const;
  /// Transformation rows: replaces the owned residual rows (after export) ...
  void replace_rows(const Vector& d_overlap, Vector& r_owned) const;
  /// ... and the owned matrix rows (after endAssembly).
  void replace_rows(FEMatrix& K) const;
  /// The owned rows (local) that replace_rows replaces.
  std::vector<int> constrained_rows() const;
  /// The modulus the collocation rows are scaled by (the largest E and 3 kappa of the model).
  double row_modulus() const { return row_modulus_; }
  /// The cell pressures in the boundary traction of the transformation conditions' points on
  /// mixed u-p parts, linearized at d: row (a, i) of the residual gains coefficient x p_c, p_c
  /// the pressure of the point's pressure cell (its rank-one part, columns x b) (operators/BulkSplit: these rows couple to the split
  /// bulk excess like the cells' own). `weak`: whether a Nitsche or penalty point has a cell
  /// pressure (its terms are not of this form; EssentialConditionsMixed.cpp).
  struct CellPressureTraction {
    std::size_t part, group;
    double volume;
    std::vector<int> rows;  ///< overlap dofs
    std::vector<double> coefficient;
    std::vector<int> columns;  ///< overlap dofs of the cell's b (theta_c = sum b x d)
    std::vector<double> b;
  };
  std::vector<CellPressureTraction> cell_pressure_tractions(const Vector& d_overlap,
                                                            bool& weak) const;

  /// Path-dependent parts: the boundary points keep a plastic history of their own (the
  /// traction term needs the stress there); the last evaluation's state becomes the committed one
  /// when the load step is accepted (as MaterialStates::commit), and is stored per condition in
  /// MaterialStates::boundary_points, which every set of conditions of the run shares.
  void commit_history();
  /// Takes the committed history of its conditions from MaterialStates (a stage begins: an
  /// earlier stage, explicit or implicit, may have advanced it). Done on construction too.
  void load_history();
  /// Evaluates the stress at every plastic boundary point at d (its trial history), without
  /// assembling anything: explicit stages keep the transformation conditions' history this way.
  void update_history(const Vector& d_overlap) const;

  /// Number of displacement and velocity conditions of the scene (the index range of totals).
  std::size_t condition_count() const { return conditions_; }

  /// Reaction force of every condition, summed over ranks, from the owned residual of the
  /// unconstrained equations r = f_int - f_ext.
  std::vector<std::array<double, 3>> reactions(const Vector& residual_owned) const;

 private:
  struct NodeConstraint {  // transformation: one collocated dof
    std::size_t condition;
    int owned_row;
    int component;
    double scale, base, value = 0;
    std::string curve;
    std::array<double, 3> X{};  // where the value is prescribed (values varying in time)
    std::vector<int> nodes;
    std::vector<double> phi;
  };
  struct BoundaryPoint {
    std::size_t condition;
    std::array<double, 3> weighted_normal{};  // n dA (x thickness in 2D)
    double area = 0;                          // dA (x thickness)
    std::array<bool, 3> constrained{};
    std::array<double, 3> base{}, value{};
    std::string curve;
    std::array<double, 3> X{};
    int method;  // 0 transformation, 1 nitsche, 2 penalty
    double beta;
    MaterialLaw law;
    std::size_t history = 0;  // plastic laws: offset of the point's state in committed_/trial_
    std::vector<int> nodes;
    std::vector<double> phi, grad;  // grad: dim per entry
    // Mixed u-p parts: the traction adds the pressure of the point's cell
    // (operators/BoundaryCellPressure); `nodes` then also hold the cell's particles, with
    // phi = grad = 0 where the point does not reach.
    BoundaryCellPressure cell_pressure;
  };
  /// A boundary point evaluated at d: the gap u^h - u_bar on its constrained components, P n dA,
  /// and S(a, k, i) = sum_jl A_kjil dphi_a/dX_l n_j dA, the traction component k of the virtual
  /// displacement phi_a e_i (one table per point: the matrix loop is quadratic in entries).
  struct PointState {
    double gap[3] = {0, 0, 0}, Pn[3] = {0, 0, 0};
    std::vector<double> S;
    int dim = 3;
    double s(std::size_t a, int k, int i) const {
      return S[(a * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)) *
                   static_cast<std::size_t>(dim) +
               static_cast<std::size_t>(i)];
    }
  };
  template <int Dim>
  PointState evaluate_point(const BoundaryPoint& p, const Vector& d_overlap,
                            BulkTangent bulk = BulkTangent::full) const;
  template <int Dim>
  void point_terms(const BoundaryPoint& p, const Vector& d_overlap, Vector* r, FEMatrix* K,
                   std::array<double, 3>* total = nullptr,
                   BulkTangent bulk = BulkTangent::full) const;
  template <int Dim>
  void point_product(const BoundaryPoint& p, const PointState& st, const Vector& x_overlap,
                     Vector& y_overlap) const;
  double constrained_value(const NodeConstraint& c, const Vector& d_overlap) const;

  void build_reaction_weights(const Model& model);
  /// P (and A when given) at a boundary point: its law, with its own history for a plastic
  /// law. Without A a plastic law runs on plain doubles: the explicit stages' history tracking
  /// needs no tangent, and the AD tangent costs about 20x the stress (it took 95 % of a Taylor
  /// impact's run time).
  template <int Dim>
  bool boundary_stress(const BoundaryPoint& p, const double (&H)[Dim][Dim], double (&P)[Dim][Dim],
                       double (*A)[Dim][Dim][Dim][Dim]) const;

  /// One displacement condition while it is being set up.
  struct Setup {
    std::size_t index = 0;
    const BoundaryConditionSpec* bc = nullptr;
    int method = 0;
    double beta_factor = 0;  ///< alpha E: beta = alpha E / h
    double modulus = 0;      ///< the largest Young's modulus (row scaling)
    std::array<bool, 3> mask{};
    /// u_bar_k(X, t), unscaled (X: 3 entries)
    std::function<double(const double*, std::size_t, double)> prescribed;
  };
  using Prescribed = std::function<double(const double*, std::size_t, double)>;
  /// Per condition: its u_bar(X, t) when a component is an expression of t (else empty): such
  /// values are evaluated again at every set_factor.
  std::vector<Prescribed> timed_;
  void add_collocated_nodes(const Model& model, const SolidOperator& op, const Setup& setup);
  long long add_boundary_points(const Model& model, const SolidOperator& op, const Setup& setup);

  int dim_;
  double row_modulus_ = 0;
  std::size_t conditions_;
  std::vector<std::vector<double>>
      reaction_weight_;  // per owned particle (node order), per condition and component
  Teuchos::RCP<const Map> overlap_dofs_;
  std::vector<NodeConstraint> nodes_;
  std::vector<BoundaryPoint> points_;
  const MaterialStates* states_ = nullptr;  // the step time of rate-dependent laws
  std::vector<double> committed_;
  mutable std::vector<double> trial_;
  MaterialStates* shared_ = nullptr;  // the run's history store (per condition)
  std::vector<std::array<std::size_t, 3>> history_ranges_;  // condition, begin, end in committed_
  template <int Dim>
  void update_point_history(const BoundaryPoint& p, const Vector& d_overlap) const;
  /// u^h and its gradient H at a boundary point (added to u and H).
  template <int Dim>
  static void interpolate_at(const BoundaryPoint& p, const Vector& d_overlap, double (&u)[Dim],
                             double (&H)[Dim][Dim]);
};

/// The boundary points' states at one d (EssentialConditions::boundary_tangent).
struct EssentialConditions::BoundaryTangent {
  std::vector<PointState> points;  ///< one per boundary point, in points_' order
};

}  // namespace efg
