// Which particles' supports cover each evaluation point: a cell-list search (PointBins) over the
// particles, O(1) work per neighbour, so O(N) in total for quasi-uniform clouds.
#pragma once

#include <cstddef>
#include <vector>

#include "discretization/ParticleCloud.hpp"

namespace efg {

/// Per-point neighbour lists in compressed rows: the neighbours of point p are
/// particles[offsets[p] .. offsets[p+1]), cloud indices ordered by global particle id so that
/// sums over neighbours run in the same order on any number of ranks.
struct NeighborLists {
  std::vector<std::size_t> offsets;
  std::vector<LocalIndex> particles;

  std::size_t point_count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::size_t count(std::size_t p) const { return offsets[p + 1] - offsets[p]; }
};

/// True when x lies strictly inside the support of particle i (box or sphere).
bool inside_support(const ParticleCloud& cloud, std::size_t i, const double* x);

/// Neighbours of `count` points (coordinates `points`, cloud.dimension per point).
NeighborLists find_neighbors(const ParticleCloud& cloud, const double* points, std::size_t count);

}  // namespace efg
