// The layout of a uniform grid of bins (a cell list): origin, bin edge and bin counts. Plain
// data, so the same object serves host queries (PointBins) and Kokkos kernels (the neighbour
// search), which both visit the bins overlapping a query box through for_each_bin_near.
#pragma once

#include <Kokkos_Macros.hpp>

#include <cstddef>
#include <cstdint>

namespace efg {

struct BinGrid {
  int dim = 3;
  double bin_size = 1.0;
  double lower[3] = {0.0, 0.0, 0.0};
  std::int64_t bins[3] = {1, 1, 1};

  KOKKOS_INLINE_FUNCTION std::size_t total() const {
    return static_cast<std::size_t>(bins[0] * bins[1] * bins[2]);
  }

  /// The bin holding x (clamped to the grid).
  KOKKOS_INLINE_FUNCTION std::size_t bin_of(const double* x) const {
    std::int64_t b[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d) {
      const auto i = static_cast<std::int64_t>((x[d] - lower[d]) / bin_size);
      b[d] = i < 0 ? 0 : (i >= bins[d] ? bins[d] - 1 : i);
    }
    return flat(b[0], b[1], b[2]);
  }

  KOKKOS_INLINE_FUNCTION std::size_t flat(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::size_t>(i + bins[0] * (j + bins[1] * k));
  }

  /// Calls visit(bin) for every bin overlapping the box x +- radius, in a fixed order.
  template <class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_bin_near(const double* x, double radius,
                                                Visit&& visit) const {
    std::int64_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d) {
      const auto l = static_cast<std::int64_t>((x[d] - radius - lower[d]) / bin_size);
      const auto h = static_cast<std::int64_t>((x[d] + radius - lower[d]) / bin_size);
      lo[d] = l < 0 ? 0 : l;
      hi[d] = h >= bins[d] ? bins[d] - 1 : h;
      if (x[d] + radius < lower[d] || lo[d] > hi[d]) return;
    }
    for (auto k = lo[2]; k <= hi[2]; ++k)
      for (auto j = lo[1]; j <= hi[1]; ++j)
        for (auto i = lo[0]; i <= hi[0]; ++i) visit(flat(i, j, k));
  }
};

}  // namespace efg
