// The Timoshenko cantilever of ../shared/reference/benchmarks.md as scene text, for tests:
// plane stress, L = 48, D = 12, E = 3e7, nu = 0.3, exact displacement on x = 0 and exact traction
// on x = L, one implicit stage.
#pragma once

#include <string>

namespace efg::test {

/// `stage_extra` is appended inside the stage's map (e.g. ", nonlinear_solver: {...}").
std::string beam_scene(int nx, int ny, double perturbation, const char* method = "transformation",
                       const char* basis = "linear", const char* integration = "scni",
                       double dilation = 2.0, const std::string& stage_extra = "");

}  // namespace efg::test
