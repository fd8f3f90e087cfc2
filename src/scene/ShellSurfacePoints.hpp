// Points of a scene on a shell surface read as a 3D mesh (mesh/SurfaceChart.hpp): probes and
// shell_point_load points given with three coordinates are projected onto the surface's chart
// (the mesh the shells work on is the chart), so that a user names them where they are in 3D.
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// For a charted surface mesh (mesh.surface set): every probe and shell_point_load point given
/// with 3 entries becomes its chart coordinates (x, y, 0) (the scene's mesh.chart, or the
/// projection). Nothing otherwise.
void chart_shell_points(Scene& scene, const BackgroundMesh& mesh);

}  // namespace efg
