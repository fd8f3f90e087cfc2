// Which particles' supports cover each evaluation point: a cell-list search (BinGrid) over the
// particles, O(1) work per neighbour, so O(N) in total for quasi-uniform clouds. The search runs
// as Kokkos kernels, one work item per point: a counting pass, a scan for the row offsets, and a
// filling pass that sorts each row by global particle id (so that sums over neighbours run in
// the same order on any number of ranks and threads). Only the bins are built on the host.
#pragma once

#include <cstddef>
#include <vector>

#include "core/DeviceArrays.hpp"
#include "discretization/ParticleCloud.hpp"
#include "geometry/BinGrid.hpp"

namespace efg {

/// Per-point neighbour lists in compressed rows: the neighbours of point p are
/// particles[offsets[p] .. offsets[p+1]), cloud indices ordered by global particle id.
struct NeighborLists {
  std::vector<std::size_t> offsets;
  std::vector<LocalIndex> particles;

  std::size_t point_count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::size_t count(std::size_t p) const { return offsets[p + 1] - offsets[p]; }
};

/// The same lists on the device.
struct DeviceNeighborLists {
  DeviceView<std::size_t*> offsets;
  DeviceView<int*> particles;
};

/// A cloud's particle arrays on the device, for the search and the MLS kernel.
struct DeviceCloud {
  DeviceView<const double**> position;  ///< particles x dim, reference positions
  DeviceView<const double**> support;   ///< particles x dim, support half-widths
  DeviceView<const LocalIndex*> global_id;
};
DeviceCloud device_cloud(const ParticleCloud& cloud);

/// A cloud on the device with its search bins, built once and searched for many batches of
/// points (SCNI evaluates its smoothing points batch by batch: building the bins and copying the
/// cloud for each batch made the setup grow as particles^2 / batch).
struct CloudIndex {
  DeviceCloud cloud;
  BinGrid grid;
  double reach = 0;  ///< largest per-axis support reach: the bins' edge
  bool sphere = false;
  DeviceView<const std::size_t*> bin_start;
  DeviceView<const std::size_t*> bin_points;
  std::size_t particles = 0;
};
CloudIndex index_cloud(const ParticleCloud& cloud);

/// Relative width of a support's edge that counts as outside: points whose normalized distance
/// r lies within it of 1 carry a weight of at most 1.5e-18 (the quadratic spline; the cubic and
/// quartic 1e-27) and are left out. Why: on a uniform grid at dilation 1.5 the SCNI smoothing
/// points (half a spacing from a particle) lie exactly 1.5 spacings from the next-but-one
/// particles, and round-off of the coordinates put them inside or outside; inside, they added
/// rows of zero weights (24.4 particles per SCNI point at dilation 1.2 and 45.7 at 1.5 on the same
/// 3D grid, measured, with identical shape functions) and every coupling they imply to the
/// stiffness graph. Wider than the round-off of dx relative to a for coordinates up to 1e4 times
/// the support.
constexpr double kSupportEdge = 1e-9;

/// True when x lies inside the support (half-widths a, or radius a[0] for a sphere) of the
/// particle at xi, by more than kSupportEdge of its size.
KOKKOS_INLINE_FUNCTION bool covers(bool sphere, int dim, const double* xi, const double* a,
                                   const double* x) {
  constexpr double inside = 1.0 - kSupportEdge;
  if (sphere) {
    double r2 = 0;
    for (int d = 0; d < dim; ++d) r2 += (x[d] - xi[d]) * (x[d] - xi[d]);
    return r2 < a[0] * a[0] * inside * inside;
  }
  for (int d = 0; d < dim; ++d) {
    const double dx = x[d] - xi[d];
    if (!((dx < 0 ? -dx : dx) < a[d] * inside)) return false;
  }
  return true;
}

/// Neighbours of the points (points x cloud dimension) on the device.
DeviceNeighborLists find_neighbors(const CloudIndex& index,
                                   const DeviceView<const double**>& points);

/// Neighbours of `count` points (coordinates `points`, cloud.dimension per point), on the host.
NeighborLists find_neighbors(const ParticleCloud& cloud, const double* points, std::size_t count);

}  // namespace efg
