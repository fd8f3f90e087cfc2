#include "scene/ShellReferenceMap.hpp"

#include <algorithm>
#include <cmath>

namespace efg {

std::array<double, 3> shell_map_position(const std::vector<ScalarField>& map, const double* xy) {
  const double p[3] = {xy[0], xy[1], 0.0};
  return {map[0].at(p, 0.0), map[1].at(p, 0.0), map[2].at(p, 0.0)};
}

ShellMapPoint shell_map_point(const std::vector<ScalarField>& map, const double* xy, double h) {
  ShellMapPoint r;
  r.position = shell_map_position(map, xy);
  for (std::size_t a = 0; a < 2; ++a) {
    const double plus[2] = {xy[0] + (a == 0 ? h : 0.0), xy[1] + (a == 1 ? h : 0.0)};
    const double minus[2] = {xy[0] - (a == 0 ? h : 0.0), xy[1] - (a == 1 ? h : 0.0)};
    const auto xp = shell_map_position(map, plus), xm = shell_map_position(map, minus);
    for (std::size_t i = 0; i < 3; ++i) r.tangent[a][i] = (xp[i] - xm[i]) / (2 * h);
  }
  return r;
}

double shell_map_step(const BackgroundMesh& mesh) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  if (mesh.is_part()) {  // a rank's part of a distributed read: the whole mesh's box
    for (std::size_t d = 0; d < 2; ++d) {
      lo[d] = mesh.global.lower[d];
      hi[d] = mesh.global.upper[d];
    }
  } else {
    for (std::size_t i = 0; i < mesh.coordinates.size(); ++i) {
      lo[i % 2] = std::min(lo[i % 2], mesh.coordinates[i]);
      hi[i % 2] = std::max(hi[i % 2], mesh.coordinates[i]);
    }
  }
  return 1e-6 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

}  // namespace efg
