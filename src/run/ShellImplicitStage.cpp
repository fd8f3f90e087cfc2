#include "run/ShellImplicitStage.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "drivers/NewtonSolver.hpp"
#include "drivers/ShellStaticProblem.hpp"
#include "run/ShellStageInputs.hpp"

namespace efg {

ShellImplicitSummary run_shell_implicit_stage(const Model& model, const FlatShellOperator& op,
                                              const StageSpec& stage, double start,
                                              double first_end, FlatShellOperator::Vector& d,
                                              const std::function<void(double)>& record) {
  const auto& scene = model.scene;
  const double end = stage.end_time, span = end - start;
  const int steps = stage.settings["load_steps"].as<int>();
  const double min_step = stage.settings["min_step_fraction"].as<double>() * span;
  const double interval = stage.output_interval.value_or(span);
  const auto ramp = [&](double time) { return std::min(1.0, time / first_end); };
  ShellStaticProblem problem(model, op, shell_supports_at(scene, stage.name, end));
  problem.start_rotations(shell_supports_at(scene, stage.name, start, ramp(start)));
  const ShellLineAndPointLoads edge_loads(model, op, stage.name);
  const auto edge_loads_at = [&](double time) {
    return [&edge_loads, time, r = ramp(time)](Vector& f) { edge_loads.add(time, r, f); };
  };
  const bool follower = has_follower_pressure(scene, stage.name);
  const auto follower_at = [&](double time) {
    return follower ? shell_pressure_at(model, stage.name, time, ramp(time), true)
                    : FlatShellOperator::Pressure{};
  };
  NewtonSolver newton(problem, stage.settings, scene.file, "stage '" + stage.name + "'");
  ShellImplicitSummary summary;
  summary.linear_solver = newton.plan().describe();
  Vector saved(d, Teuchos::Copy), increment(d.getMap());
  double t = start, dt = span / steps, previous_dt = 0, last_record = start;
  double next_output = std::min(end, start + interval);
  const bool springback = stage.settings["springback"].as<bool>();
  if (springback) {
    // The forces out of balance at the start (released supports and loads) are released
    // linearly over the stage, as the solids' springback stages do (docs/implicit.md).
    problem.set_level(shell_pressure_at(model, stage.name, start, ramp(start)),
                      shell_supports_at(scene, stage.name, start, ramp(start)),
                      edge_loads_at(start), follower_at(start));
    problem.begin_release(d);
    Log::info("  stage '" + stage.name + "': springback, releasing the forces out of balance " +
              "at the start over " + std::to_string(steps) + " load step(s)");
  }
  while (t < end - 1e-12 * span) {
    // (a step ending within round-off of the stage end ends exactly there)
    const double target = end - (t + dt) < 1e-12 * span ? end : t + dt;
    problem.set_level(shell_pressure_at(model, stage.name, target, ramp(target)),
                      shell_supports_at(scene, stage.name, target, ramp(target)),
                      edge_loads_at(target), follower_at(target));
    if (springback) problem.set_release(std::max(0.0, (end - target) / span));
    Log::info("  stage '" + stage.name + "' step " + std::to_string(summary.steps + 1) +
              ": t = " + std::to_string(target));
    Tpetra::deep_copy(saved, d);
    // The extrapolated predictor of the solids' ImplicitDriver (docs/implicit.md).
    const auto result =
        newton.solve_predicted(d, increment, previous_dt > 0 ? (target - t) / previous_dt : 0.0);
    summary.newton_iterations += result.iterations;
    std::ostringstream why;
    why << "stage '" << stage.name << "' (shells): load step " << summary.steps + 1
        << " at t = " << target << ", " << result.iterations << " Newton iterations";
    // A plastic problem's failed linear solve: the tangent of a mechanism, not a solver setting.
    const bool singular = result.linear_failure && !problem.linear();
    if (singular)
      why << ": " << result.record.reason << ", the tangent is singular (a mechanism)";
    else if (!result.failure.empty())
      why << ": " << result.failure;
    // When the stage stops, the last converged state stays in the results.
    const auto stop = [&](const std::string& message) {
      Tpetra::deep_copy(d, saved);
      if (t > last_record) record(t);
      throw NumericalError(message);
    };
    // An elastic system that cannot be solved stays so at any step size; a plastic one whose
    // tangent turned singular (a hinge with no hardening left: beyond the limit load) is cut
    // back like a Newton failure, so the run approaches the limit load from below.
    if (result.linear_failure && problem.linear()) stop(why.str());
    if (!result.converged || result.linear_failure) {
      Tpetra::deep_copy(d, saved);
      ++summary.cutbacks;
      dt /= 2;
      why << (singular ? "" : " without convergence") << " (||r||:";
      for (double r : result.residual_history) why << " " << r;
      why << ")";
      if (dt < min_step * (1 - 1e-12))
        stop(why.str() + "; the minimum step " + std::to_string(min_step) +
             " is reached (beyond a limit load, no equilibrium exists)");
      Log::warning(why.str() + "; cutting the step to " + std::to_string(dt));
      continue;
    }
    // the step's change (the next predictor's; with finite rotations the rotation dofs'
    // change is the step's rotation, taken before commit makes the frames carry it)
    increment.update(1.0, d, -1.0, saved, 0.0);
    problem.commit(d);  // the converged layers become the history; a cut-back step never does
    summary.residuals.push_back(result.residual_history);
    previous_dt = target - t;
    t = target;
    ++summary.steps;
    if (t >= next_output - 1e-12 * span) {
      record(t);
      last_record = t;
      next_output = std::min(end, next_output + interval);
    }
  }
  return summary;
}

}  // namespace efg
