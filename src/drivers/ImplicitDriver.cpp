#include "drivers/ImplicitDriver.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/Progress.hpp"
#include "drivers/BodyForceBalance.hpp"

namespace efg {

ImplicitDriver::ImplicitDriver(StaticProblem& problem, const StageSpec& stage, double start_time,
                               double first_stage_end)
    : problem_(problem), stage_(stage), start_(start_time), first_end_(first_stage_end) {}

StageSummary ImplicitDriver::run(Vector& d, const OutputHook& output) {
  const auto& scene = problem_.model().scene;
  const double end = stage_.end_time, span = end - start_;
  const int steps = stage_.settings["load_steps"].as<int>();
  const double min_step = stage_.settings["min_step_fraction"].as<double>() * span;
  const double interval = stage_.output_interval.value_or(span);
  YAML::Node settings = stage_.settings;
  const auto make_newton = [&] {
    return std::make_unique<NewtonSolver>(problem_, settings, scene.file,
                                          "stage '" + stage_.name + "'");
  };
  double earlier_setup_seconds = 0;  // of a solver given up for the direct one
  problem_.take_graph_change();      // a graph rebuilt at the stage start is the one used here
  auto newton_owner = make_newton();
  Progress progress("stage '" + stage_.name + "'", span);
  StageSummary summary;
  summary.linear_solver =
      newton_owner->plan().describe() + " (" + newton_owner->plan().reason + ")";
  double t = start_, dt = span / steps, next_output = std::min(end, start_ + interval),
         last_output = start_;
  Vector saved(d, Teuchos::Copy), increment(d.getMap());
  double previous_dt = 0;
  // Free rigid bodies of the contacts are force-controlled: placed where their contacts
  // balance their loads around each Newton solve.
  BodyForceBalance bodies(problem_, "stage '" + stage_.name + "'");
  const auto ramp_at = [&](double time) { return std::min(1.0, time / first_end_); };
  auto set_loads = [&](double time) {
    const double ramp = ramp_at(time);
    problem_.set_load_factor(curve_factor(scene, time, ramp, stage_.name));
    problem_.set_time(time);
  };
  const bool springback = stage_.settings["springback"].as<bool>();
  if (springback) {
    // The stage's equations at its start are out of balance by what it no longer holds (released
    // supports, tools, loads, an explicit state's inertia): that force is released linearly in
    // pseudo-time, as a load stepped down to zero (docs/implicit.md, "Springback").
    set_loads(start_);
    problem_.begin_release(d);
    Log::info("  stage '" + stage_.name + "': springback, releasing the forces out of balance " +
              "at the start over " + std::to_string(steps) + " load step(s)");
  }
  while (t < end - 1e-12 * span) {
    const double target = std::min(end, t + dt);
    set_loads(target);
    if (springback) problem_.set_release(std::max(0.0, (end - target) / span));
    Log::info("  stage '" + stage_.name + "' step " + std::to_string(summary.steps + 1) +
              ": t = " + std::to_string(target));
    Tpetra::deep_copy(saved, d);
    problem_.solid().history().set_step_time(target - t);
    // Extrapolated predictor: on a steady load path Newton starts near the answer instead of at
    // the last one, where a plastic step's first iterate overshot (det F <= 0 in a trial,
    // cutbacks).
    const double ratio = previous_dt > 0 ? (target - t) / previous_dt : 0.0;
    auto& newton = *newton_owner;
    const auto result = bodies.active()
                            ? bodies.solve(newton, d, increment, ratio, target, ramp_at(target))
                            : newton.solve_predicted(d, increment, ratio);
    summary.newton_iterations += result.iterations;
    summary.linear_iterations += result.linear_iterations;
    summary.newton_records.push_back(result.record);
    summary.linear_setup_seconds = earlier_setup_seconds + newton.preconditioner_seconds();
    if (result.linear_failure && newton.direct_fallback()) {
      // The automatic choice's iterative path stalled on a model it can factor: the step is
      // retried with the direct solver, which the rest of the stage keeps.
      Log::warning("stage '" + stage_.name + "': " + result.record.reason +
                   " with the automatic choice's " + newton.plan().describe() +
                   "; the stage goes on with the direct solver");
      earlier_setup_seconds = summary.linear_setup_seconds;
      settings = YAML::Clone(stage_.settings);
      settings["solver"] = "direct";
      newton_owner = make_newton();
      summary.linear_solver += ", then direct (the iterative solve stalled)";
      Tpetra::deep_copy(d, saved);
      continue;
    }
    if (result.linear_failure) {
      // The linear system itself cannot be solved (singular, or beyond the preconditioner):
      // a smaller load step has the same matrix, so cutting back would only repeat it.
      if (t > last_output) output(t, d);
      std::ostringstream why;
      why << "stage '" << stage_.name << "': load step " << summary.steps + 1
          << " at t = " << target << ", Newton iteration " << result.iterations << ": "
          << result.failure;
      throw NumericalError(why.str());
    }
    if (!result.converged) {
      Tpetra::deep_copy(d, saved);
      ++summary.cutbacks;
      dt /= 2;
      std::ostringstream why;
      why << "stage '" << stage_.name << "': Newton did not converge at t = " << target
          << " (load step " << summary.steps + 1 << ", " << result.iterations
          << " iterations, ||r||:";
      const auto& h = result.residual_history;
      for (std::size_t k = 0; k < h.size(); ++k) {
        if (h.size() > 6 && k == 3) {
          why << " ...";
          k = h.size() - 3;
        }
        why << " " << h[k];
      }
      why << ")";
      if (!result.failure.empty()) why << ": " << result.failure;
      if (dt < min_step * (1 - 1e-12)) {
        if (t > last_output) output(t, d);  // keep the last converged state in the results
        throw NumericalError(why.str() + "; the minimum step " + std::to_string(min_step) +
                             " is reached");
      }
      Log::warning(why.str() + "; cutting the step to " + std::to_string(dt));
      continue;
    }
    // Accepted: the history of the converged state becomes the start of the next load step (a
    // cut-back step above never reaches here and leaves the committed history untouched).
    problem_.commit_history(d);
    // A contact between deformable parts came within reach of new facets: the graph grew, and
    // the solver's matrix and preconditioner are made anew on it.
    if (problem_.take_graph_change()) newton_owner = make_newton();
    bodies.commit();
    increment.update(1.0, d, -1.0, saved, 0.0);
    previous_dt = target - t;
    t = target;
    ++summary.steps;
    summary.residual_histories.push_back(result.residual_history);
    progress.update(t - start_);
    if (t >= next_output - 1e-12 * span) {
      output(t, d);
      last_output = t;
      next_output = std::min(end, next_output + interval);
    }
  }
  progress.finish();
  return summary;
}

}  // namespace efg
