// Bin search for the contact between deformable parts (no Trilinos): a uniform grid over the
// facets' bounding boxes; each facet is listed in every bin its box (grown by its capture
// distance) overlaps, so the facets that may hold a particle are those of the particle's own
// bin. Rebuilt from the current positions at every force evaluation: O(facets), counting sort,
// no allocation once the sizes settle.
#pragma once

#include <cstddef>
#include <vector>

namespace efg::contact {

class FacetBins {
 public:
  /// lower/upper: per facet, dim components each (already grown by the capture distance);
  /// size: the bin edge (at least the largest box edge keeps the lists short).
  void build(int dim, const std::vector<double>& lower, const std::vector<double>& upper,
             double size);
  /// The facets whose grown boxes may contain x: [begin, end) into an index array.
  std::pair<const int*, const int*> near(const double* x) const;
  std::size_t bin_count() const { return start_.empty() ? 0 : start_.size() - 1; }

 private:
  long bin_of(const double* x) const;  // -1 outside the grid
  int dim_ = 2;
  double origin_[3] = {0, 0, 0}, size_ = 1;
  long n_[3] = {1, 1, 1};
  std::vector<int> start_, facets_;
};

}  // namespace efg::contact
