#include "shells/ShellReference.hpp"

#include <algorithm>
#include <cmath>

#include "scene/ShellReferenceMap.hpp"

namespace efg {

ShellReferencePoint shell_reference_at(const std::vector<ScalarField>& map, const double* xy,
                                       double step) {
  const auto point = shell_map_point(map, xy, step);
  ShellReferencePoint r;
  r.position = point.position;
  Vec3 t1 = point.tangent[0];
  const double n1 = std::sqrt(dot(t1, t1));
  for (auto& v : t1) v /= n1;
  Vec3 t3 = cross(point.tangent[0], point.tangent[1]);
  const double n3 = std::sqrt(dot(t3, t3));
  for (auto& v : t3) v /= n3;
  r.frame = {t1, cross(t3, t1), t3};
  r.tangent[0] = point.tangent[0];
  r.tangent[1] = point.tangent[1];
  r.metric = shell_metric(r.tangent, r.frame);
  return r;
}

std::optional<ShellReferencePoint> part_reference_at(const Model& model, std::size_t part,
                                                     const double* xy) {
  const auto& spec = *model.parts.at(part).part;
  if (!spec.shell || spec.shell->reference.empty()) return std::nullopt;
  return shell_reference_at(spec.shell->reference, xy, shell_map_step(model.mesh));
}

double edge_stretch(const Model& model, std::size_t part, const double* xy, const double* normal) {
  const auto r = part_reference_at(model, part, xy);
  if (!r) return 1.0;
  Vec3 along{};
  for (std::size_t c = 0; c < 3; ++c)
    along[c] = -normal[1] * r->tangent[0][c] + normal[0] * r->tangent[1][c];
  return std::sqrt(dot(along, along));
}

BackgroundMesh shell_reference_mesh(const Model& model) {
  const auto& flat = model.mesh;
  BackgroundMesh shown;
  shown.dimension = 3;
  shown.blocks = flat.blocks;
  shown.node_sets = flat.node_sets;
  shown.source = flat.source;
  const std::size_t nodes = flat.node_count();
  shown.coordinates.assign(3 * nodes, 0.0);
  for (std::size_t n = 0; n < nodes; ++n)
    for (std::size_t c = 0; c < 2; ++c) shown.coordinates[3 * n + c] = flat.coordinates[2 * n + c];
  for (const auto& part : model.scene.parts) {
    if (!part.shell || part.shell->reference.empty()) continue;
    for (const auto& block : flat.blocks) {
      if (std::find(part.blocks.begin(), part.blocks.end(), block.name) == part.blocks.end())
        continue;
      for (auto node : block.connectivity) {
        const auto n = static_cast<std::size_t>(node);
        const auto x = shell_map_position(part.shell->reference, flat.coordinates.data() + 2 * n);
        std::copy(x.begin(), x.end(),
                  shown.coordinates.begin() + static_cast<std::ptrdiff_t>(3 * n));
      }
    }
  }
  return shown;
}

}  // namespace efg
