#include "mesh/SideMeasures.hpp"

#include <algorithm>
#include <cmath>

namespace efg {

double side_longest_edge(const BackgroundMesh& mesh, const std::vector<LocalIndex>& nodes) {
  const auto udim = static_cast<std::size_t>(mesh.dimension);
  double h = 0;
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    double d2 = 0;
    for (std::size_t k = 0; k < udim; ++k) {
      const double dx =
          mesh.coordinates[static_cast<std::size_t>(nodes[a]) * udim + k] -
          mesh.coordinates[static_cast<std::size_t>(nodes[(a + 1) % nodes.size()]) * udim + k];
      d2 += dx * dx;
    }
    h = std::max(h, std::sqrt(d2));
  }
  return h;
}

double side_measure(const BackgroundMesh& mesh, const std::vector<LocalIndex>& nodes) {
  const auto udim = static_cast<std::size_t>(mesh.dimension);
  auto X = [&](LocalIndex n, std::size_t k) {
    return mesh.coordinates[static_cast<std::size_t>(n) * udim + k];
  };
  if (udim == 2)
    return std::hypot(X(nodes[1], 0) - X(nodes[0], 0), X(nodes[1], 1) - X(nodes[0], 1));
  double area = 0;
  for (std::size_t t = 1; t + 1 < nodes.size(); ++t) {
    double a[3], b[3];
    for (std::size_t k = 0; k < 3; ++k) {
      a[k] = X(nodes[t], k) - X(nodes[0], k);
      b[k] = X(nodes[t + 1], k) - X(nodes[0], k);
    }
    const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]};
    area += 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  }
  return area;
}

}  // namespace efg
