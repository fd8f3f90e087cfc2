#include "contact/FacetBins.hpp"

#include <algorithm>
#include <cmath>

namespace efg::contact {

namespace {
// Bins per direction of an extent: at least one, at most `cap`.
long bins_along(double extent, double size, long cap) {
  return std::clamp(static_cast<long>(std::floor(extent / size)) + 1, 1L, cap);
}
}  // namespace

void FacetBins::build(int dim, const std::vector<double>& lower, const std::vector<double>& upper,
                      double size) {
  dim_ = dim;
  const auto d = static_cast<std::size_t>(dim);
  const std::size_t count = d ? lower.size() / d : 0;
  start_.assign(2, 0);
  facets_.clear();
  n_[0] = n_[1] = n_[2] = 1;
  if (count == 0 || !(size > 0)) return;
  double hi[3] = {0, 0, 0};
  for (std::size_t k = 0; k < d; ++k) {
    origin_[k] = lower[k];
    hi[k] = upper[k];
  }
  for (std::size_t f = 1; f < count; ++f)
    for (std::size_t k = 0; k < d; ++k) {
      origin_[k] = std::min(origin_[k], lower[f * d + k]);
      hi[k] = std::max(hi[k], upper[f * d + k]);
    }
  // Keep the grid within a few bins per facet: a large empty region (parts far apart) widens
  // the bins rather than the memory.
  size_ = size;
  const double cap = 8.0 * static_cast<double>(count) + 64.0;
  for (;;) {
    double bins = 1;
    for (std::size_t k = 0; k < d; ++k) bins *= std::floor((hi[k] - origin_[k]) / size_) + 1;
    if (bins <= cap) break;
    size_ *= std::pow(bins / cap, 1.0 / dim) * 1.01;
  }
  long total = 1;
  for (std::size_t k = 0; k < d; ++k) {
    n_[k] = bins_along(hi[k] - origin_[k], size_, static_cast<long>(cap));
    total *= n_[k];
  }
  // Counting sort: how many facets per bin, then the lists.
  auto range = [&](std::size_t f, std::size_t k, long& a, long& b) {
    a = std::clamp(static_cast<long>(std::floor((lower[f * d + k] - origin_[k]) / size_)), 0L,
                   n_[k] - 1);
    b = std::clamp(static_cast<long>(std::floor((upper[f * d + k] - origin_[k]) / size_)), 0L,
                   n_[k] - 1);
  };
  start_.assign(static_cast<std::size_t>(total) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (std::size_t b = 0; b + 1 < start_.size(); ++b) start_[b + 1] += start_[b];
      facets_.assign(static_cast<std::size_t>(start_.back()), 0);
      fill.assign(start_.begin(), start_.end() - 1);
    }
    for (std::size_t f = 0; f < count; ++f) {
      long a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
      for (std::size_t k = 0; k < d; ++k) range(f, k, a[k], b[k]);
      for (long i = a[0]; i <= b[0]; ++i)
        for (long j = a[1]; j <= b[1]; ++j)
          for (long l = a[2]; l <= b[2]; ++l) {
            const auto bin = static_cast<std::size_t>((l * n_[1] + j) * n_[0] + i);
            if (pass == 0)
              ++start_[bin + 1];
            else
              facets_[static_cast<std::size_t>(fill[bin]++)] = static_cast<int>(f);
          }
    }
  }
}

long FacetBins::bin_of(const double* x) const {
  long index[3] = {0, 0, 0};
  for (int k = 0; k < dim_; ++k) {
    const double s = std::floor((x[k] - origin_[k]) / size_);
    if (!(s >= 0) || s >= static_cast<double>(n_[k])) return -1;
    index[k] = static_cast<long>(s);
  }
  return (index[2] * n_[1] + index[1]) * n_[0] + index[0];
}

std::pair<const int*, const int*> FacetBins::near(const double* x) const {
  const long bin = bin_of(x);
  if (bin < 0 || facets_.empty()) return {nullptr, nullptr};
  const auto b = static_cast<std::size_t>(bin);
  return {facets_.data() + start_[b], facets_.data() + start_[b + 1]};
}

}  // namespace efg::contact
