#include "shells/ShellReference.hpp"

#include <algorithm>
#include <cmath>

namespace efg {
namespace {

Vec3 evaluate(const std::vector<ScalarField>& map, double x, double y) {
  const double p[3] = {x, y, 0.0};
  return {map[0].at(p, 0.0), map[1].at(p, 0.0), map[2].at(p, 0.0)};
}

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

ShellReferencePoint shell_reference_at(const std::vector<ScalarField>& map, const double* xy,
                                       double length) {
  ShellReferencePoint r;
  r.position = evaluate(map, xy[0], xy[1]);
  const double h = 1e-6 * length;
  Vec3 t[2];
  for (int a = 0; a < 2; ++a) {
    const double dx = a == 0 ? h : 0.0, dy = a == 1 ? h : 0.0;
    const auto plus = evaluate(map, xy[0] + dx, xy[1] + dy);
    const auto minus = evaluate(map, xy[0] - dx, xy[1] - dy);
    for (std::size_t i = 0; i < 3; ++i) t[a][i] = (plus[i] - minus[i]) / (2 * h);
  }
  const double n1 = std::sqrt(dot(t[0], t[0]));
  for (auto& v : t[0]) v /= n1;
  Vec3 t3 = {t[0][1] * t[1][2] - t[0][2] * t[1][1], t[0][2] * t[1][0] - t[0][0] * t[1][2],
             t[0][0] * t[1][1] - t[0][1] * t[1][0]};
  const double n3 = std::sqrt(dot(t3, t3));
  for (auto& v : t3) v /= n3;
  r.frame.t1 = t[0];
  r.frame.t3 = t3;
  r.frame.t2 = {t3[1] * t[0][2] - t3[2] * t[0][1], t3[2] * t[0][0] - t3[0] * t[0][2],
                t3[0] * t[0][1] - t3[1] * t[0][0]};
  return r;
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
        const double p[3] = {flat.coordinates[2 * n], flat.coordinates[2 * n + 1], 0.0};
        for (std::size_t c = 0; c < 3; ++c)
          shown.coordinates[3 * n + c] = part.shell->reference[c].at(p, 0.0);
      }
    }
  }
  return shown;
}

}  // namespace efg
