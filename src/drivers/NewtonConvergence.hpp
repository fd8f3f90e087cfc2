// Newton's stopping test for static equilibrium, in force and energy units rather than relative to
// wherever the step happened to start (a hold stage starts converged; an exactly solved linear
// step leaves only round-off). Converged when, after the iterate's update:
//   (a) ||r|| <= tol * max(||f_ext||, ||f_int(d)||, ||r_0||, ||r_step||)   (residual against the
//       force scale; r_step the residual where the load step began before the extrapolated
//       predictor moved it, ImplicitDriver),
//   (b) the problem is linear and the linear solve of the iteration converged (one Newton step of
//       an affine residual with an exact direction is the solution: never cut back), or
//   (c) |dd_k . r_{k-1}| <= energy_tol * max(|dd_1 . r_0|, W_step)   (energy norm of the update:
//       Bathe 1996, sec. 8.4.4; it also ends iterations stuck at the round-off floor of f_int,
//       where the update is round-off too). W_step: after an extrapolated predictor, the work of
//       the unpredicted residual over the predicted increment, so that a predictor that lands on
//       the answer (a step that stays elastic: the first update is round-off already) is judged
//       against the step's energy, not against round-off.
// Fails when the linear solve of an iteration did not converge, reduced the residual of its
// system by less than 1e-3 and ||r|| by less than 10x (the direction is no Newton direction: a
// singular or hopeless system),
// or when ||r|| grows above 1e3 ||r_0|| (divergence; 1e3 max(||r_0||, ||r_1||) for problems
// Newton solves by full steps, NonlinearProblem::residual_norm_is_a_merit). Keeps the
// per-iteration record the log and the run report print.
#pragma once

#include <NOX_Abstract_Vector.H>
#include <NOX_StatusTest_Generic.H>

#include <functional>
#include <string>
#include <vector>

#include "drivers/NonlinearProblem.hpp"

namespace efg {

struct NewtonRecord {
  std::vector<double> residuals;          ///< ||r|| before the first and after every iteration
  std::vector<int> linear_iterations;     ///< per iteration
  std::vector<double> linear_reductions;  ///< ||J dd + r|| / ||r|| per iteration
  std::vector<bool> linear_converged;     ///< per iteration
  std::string reason;                     ///< which test ended the iteration (or why it failed)
  bool linear_failure = false;            ///< the linear solver, not Newton, failed
};

class NewtonConvergence : public NOX::StatusTest::Generic {
 public:
  /// ||J dd + r|| / ||r|| with the Jacobian of the previous iterate (dd: the Newton direction).
  using LinearResidualRatio =
      std::function<double(const NOX::Abstract::Vector& dd, const NOX::Abstract::Vector& r)>;

  /// `step_scale`: the residual norm of the load step's start before a predictor moved it (0:
  /// none), kept in the force scale so that a predicted start judges by the step's forces.
  /// `step_energy`: W_step of (c) (0: none).
  NewtonConvergence(const NonlinearProblem& problem, double tolerance, double energy_tolerance,
                    LinearResidualRatio ratio, NewtonRecord& record, double step_scale = 0.0,
                    double step_energy = 0.0)
      : problem_(problem),
        tol_(tolerance),
        energy_tol_(energy_tolerance),
        ratio_(std::move(ratio)),
        record_(record),
        step_scale_(step_scale),
        step_energy_(step_energy) {}

  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent) const override;

 private:
  void record_linear_solve(const NOX::Solver::Generic& solver, const NOX::Abstract::Vector& update);

  const NonlinearProblem& problem_;
  double tol_, energy_tol_;
  LinearResidualRatio ratio_;
  NewtonRecord& record_;
  double first_energy_ = 0, step_scale_ = 0, step_energy_ = 0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace efg
