// A uniform grid of bins over a point cloud, for fixed-radius neighbour queries in O(1) bins per
// query (a cell list). Used by the ghost layer and the meshfree support search.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace efg {

class PointBins {
 public:
  /// Bins the `count` points of `coords` (dim components each) with bins of edge `bin_size`.
  PointBins(const double* coords, std::size_t count, int dim, double bin_size);

  /// Calls visit(index) for every point within Euclidean distance `radius` of `x`, each once.
  template <class Visit>
  void for_each_within(const double* x, double radius, Visit&& visit) const;

  int dimension() const { return dim_; }

 private:
  std::array<std::int64_t, 3> bin_of(const double* x) const;
  std::size_t flat(const std::array<std::int64_t, 3>& b) const;

  const double* coords_;
  int dim_;
  double bin_size_;
  std::array<double, 3> lower_{};
  std::array<std::int64_t, 3> bins_{1, 1, 1};
  std::vector<std::size_t> start_;   ///< CSR offsets per bin
  std::vector<std::size_t> points_;  ///< point indices sorted by bin
};

template <class Visit>
void PointBins::for_each_within(const double* x, double radius, Visit&& visit) const {
  std::array<std::int64_t, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    const auto du = static_cast<std::size_t>(d);
    if (d >= dim_) {
      lo[du] = hi[du] = 0;
      continue;
    }
    const auto l = static_cast<std::int64_t>((x[d] - radius - lower_[du]) / bin_size_);
    const auto h = static_cast<std::int64_t>((x[d] + radius - lower_[du]) / bin_size_);
    lo[du] = l < 0 ? 0 : l;
    hi[du] = h >= bins_[du] ? bins_[du] - 1 : h;
    if (x[d] + radius < lower_[du] || lo[du] > hi[du]) return;
  }
  const double r2 = radius * radius;
  for (auto k = lo[2]; k <= hi[2]; ++k)
    for (auto j = lo[1]; j <= hi[1]; ++j)
      for (auto i = lo[0]; i <= hi[0]; ++i) {
        const auto b = flat({i, j, k});
        for (auto p = start_[b]; p < start_[b + 1]; ++p) {
          const auto n = points_[p];
          double d2 = 0;
          for (int d = 0; d < dim_; ++d) {
            const double dx = coords_[n * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(d)] - x[d];
            d2 += dx * dx;
          }
          if (d2 <= r2) visit(n);
        }
      }
}

}  // namespace efg
