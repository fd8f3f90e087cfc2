// A uniform grid of bins over a point cloud, for fixed-radius neighbour queries in O(1) bins per
// query (a cell list). Used by the ghost layer on the host; the meshfree support search copies
// its arrays to the device (discretization/NeighborSearch.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/BinGrid.hpp"

namespace efg {

class PointBins {
 public:
  /// Bins the `count` points of `coords` (dim components each) with bins of edge `bin_size`
  /// (enlarged when the grid would hold far more bins than points).
  PointBins(const double* coords, std::size_t count, int dim, double bin_size);

  /// Calls visit(index) for every point within Euclidean distance `radius` of `x`, each once.
  template <class Visit>
  void for_each_within(const double* x, double radius, Visit&& visit) const;

  /// True when some point lies within Euclidean distance `radius` of `x`.
  bool any_within(const double* x, double radius) const;

  int dimension() const { return grid_.dim; }
  const BinGrid& grid() const { return grid_; }
  const std::vector<std::size_t>& bin_start() const { return start_; }    ///< CSR offsets per bin
  const std::vector<std::size_t>& bin_points() const { return points_; }  ///< point indices by bin

 private:
  /// Squared distance from point n to x.
  double distance2(std::size_t n, const double* x) const {
    const auto dim = static_cast<std::size_t>(grid_.dim);
    double d2 = 0;
    for (std::size_t d = 0; d < dim; ++d) {
      const double dx = coords_[n * dim + d] - x[d];
      d2 += dx * dx;
    }
    return d2;
  }

  const double* coords_;
  BinGrid grid_;
  std::vector<std::size_t> start_;
  std::vector<std::size_t> points_;
};

template <class Visit>
void PointBins::for_each_within(const double* x, double radius, Visit&& visit) const {
  const double r2 = radius * radius;
  grid_.for_each_bin_near(x, radius, [&](std::size_t b) {
    for (auto p = start_[b]; p < start_[b + 1]; ++p)
      if (distance2(points_[p], x) <= r2) visit(points_[p]);
  });
}

}  // namespace efg
