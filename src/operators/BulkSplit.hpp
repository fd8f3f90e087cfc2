// The mixed u-p parts' bulk stiffness as a saddle point for the iterative solver
// (solvers/BulkSplitPreconditioner.cpp). At small strain the condensed Jacobian of a nearly
// incompressible part is linear in its bulk modulus kappa = kappa_0 + kappa_1:
//   K = A + C^T D_1 B,   D_1 = diag(V_c kappa_1),
// with A the Jacobian at kappa_0 = 5 mu / 3 (nu_0 = 1/4: compressible, where multigrid
// converges; assembled as such, not as K - C^T D_1 B: operators/BulkTangent.hpp), B the cells' average dilatations (rows b_c, theta_c = b_c . d) and C^T q the
// forces of cell pressures q_c / V_c: the cells' own (b_c, zero in the rows the transformation
// method replaces) and the transformation conditions' boundary tractions
// (EssentialConditionsMixed.cpp), which carry kappa as well. K du = f is the first row of
//   [ A          C^T D^1/2 ] [du]   [f]
//   [ D^1/2 B    -I        ] [p ] = [0],      p = D^1/2 B du,
// whose Schur complement I + D^1/2 B A^-1 C^T D^1/2 is taken as diag(1 + kappa_1 / M_0),
// M_0 = kappa_0 + 4 mu / 3 (a cell's dilatation under its own pressure); for an inf-sup stable
// pairing this is spectrally equivalent to the true one whatever kappa_1 (Brezzi & Fortin 1991;
// for block preconditioners of elasticity: Klawonn 1998), which is the point: the iteration count
// does not grow as nu -> 1/2. The scaling by D^1/2 keeps a residual of the pressure rows from
// reaching K's multiplied by kappa (unscaled) or the matrix's conditioning (scaled by D).
// The collocation rows of A are scaled by the modulus at kappa_0 (K's follow 3 kappa).
// Finite strain (total Lagrangian neo-Hookean cells, U = kappa/2 (ln J)^2): the cells' tangent
// V kappa (g (x) g - ln J_c g_Ij g_Ji), g_c = F_c^-T b_c, splits the same way with B's rows g_c
// at the Jacobian's state; the second term, kappa ln J = the pressure's size, stays in A.
#pragma once

#include <Tpetra_CrsMatrix.hpp>

#include <string>
#include <vector>

#include "operators/EssentialConditions.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

/// Why the split does not apply to this model ("" when it does): no mixed part with kappa above
/// kappa_0, or Nitsche/penalty conditions on a mixed part.
std::string bulk_split_misfit(const ModelOperators& ops, const EssentialConditions& conditions);

/// The blocks of the saddle point on this rank's pressure cells (MixedPressure's order).
class BulkCoupling {
 public:
  BulkCoupling(const ModelOperators& ops, const EssentialConditions& conditions);
  std::size_t cells() const { return cells_; }
  /// q = D_1 B x (owned x).
  void pressures(const Vector& x_owned, double* q) const;
  /// y = C^T q (owned y; zero on the collocation rows).
  void forces(const double* q, Vector& y_owned) const;
  /// A = K - C^T D_1 B at the state d (K's): `relieved_tangent`, the Jacobian assembled at d
  /// with the mixed parts' bulk stiffness at kappa_0 (operators/BulkTangent.hpp), its
  /// collocation rows replaced by K's scaled by row_factor(). Sets the state of pressures() and
  /// forces() (finite strain: g_c = F_c^-T b_c and F^-T N at d).
  Teuchos::RCP<const Tpetra::CrsMatrix<>> relieved(const Tpetra::CrsMatrix<>& K,
                                                   const FEMatrix& relieved_tangent,
                                                   const Vector& d_overlap);
  double row_factor() const { return row_factor_; }
  const std::vector<int>& constrained_rows() const { return constrained_; }

 private:
  const ModelOperators& ops_;
  const EssentialConditions& conditions_;
  std::vector<int> constrained_;
  std::vector<EssentialConditions::CellPressureTraction> tractions_;
  std::vector<int> traction_cell_;  // each traction's entry in the overlap pressures
  std::size_t cells_ = 0;
  bool any_tractions_ = false;  // on some rank
  double row_factor_ = 1;
  Teuchos::RCP<const Tpetra::Map<>> owned_cells_, overlap_cells_;
  Teuchos::RCP<Tpetra::Import<>> import_;
  mutable Vector x_overlap_, y_overlap_;
  Teuchos::RCP<Vector> q_owned_, q_overlap_;  // the cells' pressures, owned and overlap
};

}  // namespace efg
