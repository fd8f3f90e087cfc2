#include "scene/ShellSurfacePoints.hpp"

#include "mesh/SurfaceChart.hpp"

namespace efg {

void chart_shell_points(Scene& scene, const BackgroundMesh& mesh) {
  if (mesh.surface.empty()) return;
  const auto projection = surface_projection(mesh);
  const auto to_chart = [&](std::array<double, 3>& point) {
    auto c = chart_coordinates(projection, point.data());
    if (scene.surface_chart) scene.surface_chart(point.data(), c.data());
    point = {c[0], c[1], 0.0};
  };
  const auto& d = scene.document;
  for (std::size_t i = 0; i < scene.probes.size(); ++i)
    if (d["probes"][i]["point"].size() == 3) to_chart(scene.probes[i].point);
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    if (scene.loads[i].type == "shell_point_load" && d["loads"][i]["point"].size() == 3)
      to_chart(scene.loads[i].point);
}

}  // namespace efg
