// An implicit (static) stage: load steps from the stage's start to its end time, each solved by
// Newton; a step whose Newton iteration fails is retried at half the size until the stage's
// minimum step, then the run stops (exit 3) naming the time and the residual history.
//
// Loads and prescribed values follow their curves; without a curve they rise linearly from 0 at
// time 0 to their full value at the end of the first stage and then stay there.
#pragma once

#include <functional>

#include "drivers/NewtonSolver.hpp"
#include "drivers/StaticProblem.hpp"

namespace efg {

/// Called after every converged step that reaches an output time: (time, generalized d).
using OutputHook = std::function<void(double, const Vector&)>;

struct StageSummary {
  int steps = 0, cutbacks = 0, newton_iterations = 0, linear_iterations = 0;
  std::vector<std::vector<double>>
      residual_histories;                    ///< ||r|| per Newton iteration, per converged step
  std::vector<NewtonRecord> newton_records;  ///< every Newton solve, cut back ones included
  std::string linear_solver;                 ///< what solved the linear systems, and why
  double linear_setup_seconds = 0;           ///< preconditioner builds / factorizations
};

class ImplicitDriver {
 public:
  ImplicitDriver(StaticProblem& problem, const StageSpec& stage, double start_time,
                 double first_stage_end);

  /// Advances d (owned generalized displacements) through the stage.
  StageSummary run(Vector& d, const OutputHook& output);

 private:
  StaticProblem& problem_;
  const StageSpec& stage_;
  double start_, first_end_;
};

}  // namespace efg
