// Essential conditions of shells in explicit stages: the collocation constraints C d = g of
// ShellConstraints (physical values at the particles of the held edges) enforced by forward-
// increment Lagrange multipliers (Carpenter, Taylor & Katona, IJNME 32, 1991, 103-128):
//
//   predicted  d~ = central-difference update without the constraints,
//   (C M^-1 C^T) y = C d~ - g,   d_(n+1) = d~ - M^-1 C^T y,   lambda = y / dt^2,
//
// i.e. the M-orthogonal projection of the prediction onto the constraints, the force -C^T lambda
// acting in the step. With the lumped mass M, C M^-1 C^T couples only particles of one edge and is
// factored once per stage (the direct solver). Unlike the implicit stages' row replacement with
// its nonsymmetric edge terms (shells/ShellConstraints), the multipliers carry the reaction
// themselves: the semi-discrete system stays symmetric, the held supports do no work and the
// stable step of the unconstrained system bounds the constrained one (the projection cannot
// raise the largest frequency).
#pragma once

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <vector>

#include "solvers/MatrixPreconditioner.hpp"

namespace efg {

class ShellConstraints;

class ShellMultipliers {
 public:
  using Vector = Tpetra::Vector<>;

  ShellMultipliers(const ShellConstraints& constraints, const Vector& mass_owned);

  /// Projects d (owned, the unconstrained prediction) onto C d = g; adds the constraint force
  /// -C^T lambda = -C^T y / dt^2 to `force_owned` when given (the supports' reaction is its
  /// negative). Collective.
  void correct(Vector& d_owned, double dt, Vector* force_owned = nullptr) const;

  /// The number of constrained dofs (all ranks).
  long long count() const { return count_; }

  /// New values g of the rows (ShellConstraints::collocation_values: moving supports).
  void set_values(const std::vector<double>& g);

  /// Adds the last correct()'s constraint impulse over a step dt, -lambda dt per row (local: no
  /// communication; a moving support's multipliers ring from step to step, their mean does not).
  void accumulate_impulse(double dt);
  /// The mean force each support applied to the shell since the previous call, per component:
  /// 5 entries per support, -sum_J lambda_J over its rows (the shape functions sum to one, so
  /// that is the total of -C^T lambda), the accumulated impulse over `elapsed`; with elapsed 0
  /// the last correct()'s force. Resets the impulse. Collective.
  std::vector<double> mean_support_forces(std::size_t supports, double elapsed);

 private:
  Teuchos::RCP<Tpetra::CrsMatrix<>> C_;
  Teuchos::RCP<MatrixPreconditioner> solver_;
  Teuchos::RCP<Vector> g_;
  Vector inv_mass_;
  mutable Vector r_, y_, correction_;
  mutable double dt_ = 1.0;  ///< of the last correct()
  std::vector<std::pair<int, int>> row_supports_;
  std::vector<double> impulse_;  ///< per row of this rank, since the last mean_support_forces
  long long count_ = 0;
};

}  // namespace efg
