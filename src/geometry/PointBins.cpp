#include "geometry/PointBins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace efg {

PointBins::PointBins(const double* coords, std::size_t count, int dim, double bin_size)
    : coords_(coords), dim_(dim), bin_size_(bin_size) {
  if (!(bin_size > 0)) throw std::invalid_argument("PointBins: bin size must be positive");
  std::array<double, 3> upper{};
  for (int d = 0; d < dim; ++d) {
    const auto du = static_cast<std::size_t>(d);
    lower_[du] = std::numeric_limits<double>::max();
    upper[du] = std::numeric_limits<double>::lowest();
    for (std::size_t n = 0; n < count; ++n) {
      lower_[du] = std::min(lower_[du], coords[n * static_cast<std::size_t>(dim) + du]);
      upper[du] = std::max(upper[du], coords[n * static_cast<std::size_t>(dim) + du]);
    }
    if (count == 0) lower_[du] = upper[du] = 0;
    // Cap the bin count per direction so that a tiny bin size cannot exhaust memory.
    const double span = (upper[du] - lower_[du]) / bin_size;
    bins_[du] = static_cast<std::int64_t>(std::min(span, 1e6)) + 1;
  }
  // Keep the total number of bins near the number of points at most.
  while (static_cast<double>(bins_[0]) * static_cast<double>(bins_[1]) * static_cast<double>(bins_[2]) >
         8.0 * static_cast<double>(count) + 64.0) {
    bin_size_ *= 2.0;
    for (int d = 0; d < dim; ++d) {
      const auto du = static_cast<std::size_t>(d);
      bins_[du] = static_cast<std::int64_t>((upper[du] - lower_[du]) / bin_size_) + 1;
    }
  }
  const auto total = static_cast<std::size_t>(bins_[0] * bins_[1] * bins_[2]);
  start_.assign(total + 1, 0);
  std::vector<std::size_t> bin(count);
  for (std::size_t n = 0; n < count; ++n) {
    bin[n] = flat(bin_of(coords + n * static_cast<std::size_t>(dim)));
    ++start_[bin[n] + 1];
  }
  for (std::size_t b = 0; b < total; ++b) start_[b + 1] += start_[b];
  points_.resize(count);
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t n = 0; n < count; ++n) points_[fill[bin[n]]++] = n;
}

std::array<std::int64_t, 3> PointBins::bin_of(const double* x) const {
  std::array<std::int64_t, 3> b{0, 0, 0};
  for (int d = 0; d < dim_; ++d) {
    const auto du = static_cast<std::size_t>(d);
    auto i = static_cast<std::int64_t>((x[d] - lower_[du]) / bin_size_);
    b[du] = std::clamp<std::int64_t>(i, 0, bins_[du] - 1);
  }
  return b;
}

std::size_t PointBins::flat(const std::array<std::int64_t, 3>& b) const {
  return static_cast<std::size_t>(b[0] + bins_[0] * (b[1] + bins_[1] * b[2]));
}

}  // namespace efg
