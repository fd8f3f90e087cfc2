// Evaluation of a shell's reference map (parts[].shell.reference: X(x, y), Y, Z as expressions of
// the mesh's x, y; docs/shells.md "Curved references"): the mapped point and its tangents by
// central differences. Shared by the scene's regularity check (scene/ShellChecks) and the shells'
// reference frames (shells/ShellReference), so both see the same tangents.
#pragma once

#include <array>
#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

struct ShellMapPoint {
  std::array<double, 3> position{};
  std::array<double, 3> tangent[2]{};  ///< dX/dx, dX/dy
};

/// X(x, y) of the map.
std::array<double, 3> shell_map_position(const std::vector<ScalarField>& map, const double* xy);
/// X(x, y) and its tangents by central differences of step h.
ShellMapPoint shell_map_point(const std::vector<ScalarField>& map, const double* xy, double h);
/// The difference step for a mesh: 1e-6 of the diagonal of its bounding box (2D coordinates).
double shell_map_step(const BackgroundMesh& mesh);

}  // namespace efg
