// What NOX's Newton (drivers/NewtonSolver) needs of an implicit problem: the residual r(d) and
// its Jacobian on a graph built once, the force scale of its convergence test, and whether it is
// affine. The solids' StaticProblem and the shells' ShellStaticProblem implement it, so both
// formulations share one Newton, one linear-solver plan and one set of stopping tests.
#pragma once

#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include <string>

#include "model/Model.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {

using Vector = Tpetra::Vector<>;
using FEMatrix = Tpetra::FECrsMatrix<>;

class NonlinearProblem {
 public:
  virtual ~NonlinearProblem() = default;

  /// r = residual(d) on the owned dofs.
  virtual void residual(const Vector& d_owned, Vector& r_owned) = 0;
  /// K = dr/dd, refilled in place (the graph never changes).
  virtual void jacobian(const Vector& d_owned, FEMatrix& K) = 0;
  virtual Teuchos::RCP<FEMatrix> create_matrix() const = 0;
  virtual const Teuchos::RCP<const Tpetra::Map<>>& owned_dofs() const = 0;
  /// The force scale of the last residual evaluation (drivers/NewtonConvergence).
  virtual double force_scale() const = 0;
  /// True when r(d) is affine in d: one Newton step with a converged linear solve solves it.
  virtual bool linear() const = 0;
  /// The model (mesh dimension, particle maps and coordinates for the linear-solver plan).
  virtual const Model& model() const = 0;
  /// False when the dofs are not the solid's displacements (shells: five per particle), so the
  /// multigrid's rigid-body modes do not apply: the plan is then the direct solver.
  virtual bool displacement_dofs() const { return true; }
  /// False when ||r|| is no fit merit function for a backtracking line search, so that Newton
  /// takes full steps (cutbacks still guard it): shells with finite rotations, whose membrane
  /// forces are (L/t)^2 stiffer than their bending ones, so that a step that removes a bending
  /// residual leaves a second-order membrane residual larger than it; Newton's full step
  /// removes that one next, a line search on ||r|| crawls (docs/shells.md).
  virtual bool residual_norm_is_a_merit() const { return true; }
  /// The auxiliary space of the iterative solver (operators/AuxiliaryStiffness): whether it fits
  /// (empty) or why not, whether it cannot stand in at all (empty: it can), and its matrix from
  /// the Jacobian K of the current stage.
  virtual std::string auxiliary_misfit() const { return "not a solid model"; }
  virtual std::string auxiliary_impossible() const { return "not a solid model"; }
  virtual Teuchos::RCP<const Tpetra::CrsMatrix<>> auxiliary_matrix(
      const Tpetra::CrsMatrix<>& /*K*/) const {
    return Teuchos::null;
  }
  /// The mixed u-p parts' bulk split of the iterative solver (operators/BulkSplit): why it does
  /// not apply ("" when it does), and the blocks of its saddle point.
  virtual std::string bulk_split_misfit() const { return "not a solid problem"; }
  virtual BulkSplit bulk_split() { return {}; }
};

}  // namespace efg
