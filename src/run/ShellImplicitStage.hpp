// An implicit stage of flat shells with J2 parts or finite rotations: load steps from the stage's start to its end
// (loads and supports at each step's time; those without a curve ramp linearly over the first
// stage, as the solids'), each solved by the NOX Newton of the solids (drivers/NewtonSolver) on
// drivers/ShellStaticProblem, with the extrapolated predictor and cutbacks of the solids'
// ImplicitDriver; the layers' history is committed when a load step converges and never
// otherwise. Elastic shell stages keep their single direct solve (run/ShellRun).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "model/Model.hpp"
#include "shells/FlatShellOperator.hpp"

namespace efg {

struct ShellImplicitSummary {
  long long steps = 0, cutbacks = 0, newton_iterations = 0;
  std::string linear_solver;
  /// ||r|| before the first and after every Newton iteration of each converged load step
  std::vector<std::vector<double>> residuals;
};

/// Runs `stage` from `start` to its end_time (d: owned dofs, in place, the converged state of
/// the last load step); `record(t)` at every output_interval and at the end. `first_end`: the end
/// of the scene's first stage (the ramp of loads without a curve). Throws NumericalError when a
/// load step cannot be solved with the smallest step allowed (min_step_fraction).
ShellImplicitSummary run_shell_implicit_stage(const Model& model, const FlatShellOperator& op,
                                              const StageSpec& stage, double start,
                                              double first_end, FlatShellOperator::Vector& d,
                                              const std::function<void(double)>& record);

}  // namespace efg
