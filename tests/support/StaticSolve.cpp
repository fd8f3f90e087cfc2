#include "support/StaticSolve.hpp"

#include <Tpetra_Core.hpp>

#include "scene/SceneReader.hpp"

namespace efg::test {

StaticSolution solve_static(const std::string& scene_text, const std::string& name) {
  StaticSolution s;
  const auto comm = Tpetra::getDefaultComm();
  s.model = std::make_unique<Model>(build_model(comm, parse_scene(scene_text, name)));
  s.problem = std::make_unique<StaticProblem>(*s.model);
  s.d = std::make_unique<Vector>(s.model->maps.owned_dofs);
  double start = 0;
  const double first_end = s.model->scene.stages.front().end_time;
  for (const auto& stage : s.model->scene.stages) {
    ImplicitDriver driver(*s.problem, stage, start, first_end);
    const auto summary = driver.run(*s.d, [](double, const Vector&) {});
    s.summary.steps += summary.steps;
    s.summary.newton_iterations += summary.newton_iterations;
    s.summary.linear_iterations += summary.linear_iterations;
    s.summary.residual_histories.insert(s.summary.residual_histories.end(),
                                        summary.residual_histories.begin(),
                                        summary.residual_histories.end());
    start = stage.end_time;
  }
  s.d_overlap = std::make_unique<Vector>(s.model->maps.overlap_dofs);
  s.problem->to_overlap(*s.d, *s.d_overlap);
  return s;
}

}  // namespace efg::test
