#include "geometry/PointBins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace efg {

PointBins::PointBins(const double* coords, std::size_t count, int dim, double bin_size)
    : coords_(coords) {
  if (!(bin_size > 0)) throw std::invalid_argument("PointBins: bin size must be positive");
  grid_.dim = dim;
  grid_.bin_size = bin_size;
  double upper[3] = {0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    grid_.lower[d] = std::numeric_limits<double>::max();
    upper[d] = std::numeric_limits<double>::lowest();
    for (std::size_t n = 0; n < count; ++n) {
      grid_.lower[d] = std::min(
          grid_.lower[d], coords[n * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)]);
      upper[d] = std::max(upper[d],
                          coords[n * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)]);
    }
    if (count == 0) grid_.lower[d] = upper[d] = 0;
    // Cap the bin count per direction so that a tiny bin size cannot exhaust memory.
    const double span = (upper[d] - grid_.lower[d]) / bin_size;
    grid_.bins[d] = static_cast<std::int64_t>(std::min(span, 1e6)) + 1;
  }
  // Keep the total number of bins near the number of points at most.
  while (static_cast<double>(grid_.total()) > 8.0 * static_cast<double>(count) + 64.0) {
    grid_.bin_size *= 2.0;
    for (int d = 0; d < dim; ++d)
      grid_.bins[d] = static_cast<std::int64_t>((upper[d] - grid_.lower[d]) / grid_.bin_size) + 1;
  }
  const auto total = grid_.total();
  start_.assign(total + 1, 0);
  std::vector<std::size_t> bin(count);
  for (std::size_t n = 0; n < count; ++n) {
    bin[n] = grid_.bin_of(coords + n * static_cast<std::size_t>(dim));
    ++start_[bin[n] + 1];
  }
  for (std::size_t b = 0; b < total; ++b) start_[b + 1] += start_[b];
  points_.resize(count);
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t n = 0; n < count; ++n) points_[fill[bin[n]]++] = n;
}

bool PointBins::any_within(const double* x, double radius) const {
  const double r2 = radius * radius;
  bool found = false;
  grid_.for_each_bin_near(x, radius, [&](std::size_t b) {
    for (auto p = start_[b]; p < start_[b + 1] && !found; ++p)
      found = distance2(points_[p], x) <= r2;
  });
  return found;
}

}  // namespace efg
