#include "discretization/NeighborSearch.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/PointBins.hpp"

namespace efg {

bool inside_support(const ParticleCloud& cloud, std::size_t i, const double* x) {
  const auto* xi = cloud.x(i);
  const auto* a = cloud.a(i);
  if (cloud.section.support == SupportShape::sphere) {
    double r2 = 0;
    for (int d = 0; d < cloud.dimension; ++d) r2 += (x[d] - xi[d]) * (x[d] - xi[d]);
    return r2 < a[0] * a[0];
  }
  for (int d = 0; d < cloud.dimension; ++d)
    if (!(std::abs(x[d] - xi[d]) < a[d])) return false;
  return true;
}

NeighborLists find_neighbors(const ParticleCloud& cloud, const double* points, std::size_t count) {
  NeighborLists lists;
  lists.offsets.assign(count + 1, 0);
  if (cloud.size() == 0) return lists;
  const double reach = largest_support_radius(cloud);
  const PointBins bins(cloud.position.data(), cloud.size(), cloud.dimension, reach);
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  std::vector<LocalIndex> found;
  lists.particles.reserve(count * (dim == 3 ? 40 : 16));
  for (std::size_t p = 0; p < count; ++p) {
    const double* x = points + p * dim;
    found.clear();
    bins.for_each_within(x, reach, [&](std::size_t i) {
      if (inside_support(cloud, i, x)) found.push_back(static_cast<LocalIndex>(i));
    });
    std::sort(found.begin(), found.end(), [&](LocalIndex a, LocalIndex b) {
      return cloud.mesh_node[static_cast<std::size_t>(a)] < cloud.mesh_node[static_cast<std::size_t>(b)];
    });
    lists.particles.insert(lists.particles.end(), found.begin(), found.end());
    lists.offsets[p + 1] = lists.particles.size();
  }
  return lists;
}

}  // namespace efg
