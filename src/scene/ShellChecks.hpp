// Cross-checks of shell scenes (parts[].shell, rotation conditions, shell_pressure loads): what
// this version of the shell formulation (src/shells) runs, and the shell keys refused in solid
// scenes. Each refusal names the file, line, column and key path (exit 2).
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

void check_shell_scene(const Scene& scene, const BackgroundMesh& mesh);

}  // namespace efg
