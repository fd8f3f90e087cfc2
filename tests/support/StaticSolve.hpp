// Runs the implicit stages of a scene given as text, in-process, for verification tests.
#pragma once

#include <memory>
#include <string>

#include "drivers/ImplicitDriver.hpp"

namespace efg::test {

struct StaticSolution {
  std::unique_ptr<Model> model;
  std::unique_ptr<StaticProblem> problem;
  std::unique_ptr<Vector> d, d_overlap;  ///< generalized displacements (owned, overlap)
  StageSummary summary;
};

StaticSolution solve_static(const std::string& scene_text, const std::string& name = "test.yaml");

}  // namespace efg::test
