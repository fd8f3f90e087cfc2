#include "contact/MeshSurface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/ClosestFeature.hpp"

namespace efg::contact {

namespace {

double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

MeshSurface::MeshSurface(std::shared_ptr<const RigidSurface> surface)
    : surface_(std::move(surface)), pseudo_(*surface_) {
  const auto& s = *surface_;
  const auto dim = static_cast<std::size_t>(s.dim);
  const auto per = static_cast<std::size_t>(s.nodes_per_facet);
  for (double h : s.reference_size) reach_ = std::max(reach_, h);
  // Every facet's box grown by the capture depth, the median facet's size (one depth for all:
  // a point within it of the surface then lies in the grown box of its nearest facet, so the
  // nearest found is the nearest of all - grown by each facet's own size, a large sliver facet
  // of a round body's rim captured points far beyond the small facets beside it, and its plane
  // alone judged them inside); bins of that size (a few large facets, e.g. a die's sides, must
  // not widen every bin: they are listed in each bin they overlap, which keeps the search exact
  // whatever the bin size).
  std::vector<double> sizes = s.reference_size;
  double median_size = 0;
  if (!sizes.empty()) {
    auto middle = sizes.begin() + static_cast<long>(sizes.size() / 2);
    std::nth_element(sizes.begin(), middle, sizes.end());
    median_size = *middle;
  }
  std::vector<double> lower(s.count() * dim), upper(s.count() * dim);
  for (std::size_t f = 0; f < s.count(); ++f) {
    const double grow = median_size;
    for (std::size_t k = 0; k < dim; ++k) {
      double lo = 1e300, hi = -1e300;
      for (std::size_t a = 0; a < per; ++a) {
        lo = std::min(lo, s.corners[3 * (per * f + a) + k]);
        hi = std::max(hi, s.corners[3 * (per * f + a) + k]);
      }
      lower[f * dim + k] = lo - grow;
      upper[f * dim + k] = hi + grow;
      tight_lower_.push_back(lo);
      tight_upper_.push_back(hi);
    }
  }
  bins_.build(s.dim, lower, upper, median_size);
  box_lower_ = std::move(lower);
  box_upper_ = std::move(upper);
  capture_ = median_size;
}

Proximity MeshSurface::proximity(const double* y) const {
  const auto& s = *surface_;
  const auto per = static_cast<std::size_t>(s.nodes_per_facet);
  Proximity p;
  p.gap = reach_;  // no facet near: at least this far
  const auto [begin, end] = bins_.near(y);
  const auto dim = static_cast<std::size_t>(s.dim);
  const auto in_box = [&](int f) {  // the facet's grown box holds y: it may capture it
    for (std::size_t k = 0; k < dim; ++k) {
      const auto i = static_cast<std::size_t>(f) * dim + k;
      if (y[k] < box_lower_[i] || y[k] > box_upper_[i]) return false;
    }
    return true;
  };
  // A lower bound of y's distance to facet f: to its tight box (a facet farther than the
  // nearest found so far is not computed).
  const auto box_distance = [&](int f) {
    double d2 = 0;
    for (std::size_t k = 0; k < dim; ++k) {
      const auto i = static_cast<std::size_t>(f) * dim + k;
      const double out = std::max({tight_lower_[i] - y[k], 0.0, y[k] - tight_upper_[i]});
      d2 += out * out;
    }
    return std::sqrt(d2);
  };
  const auto closest = [&](int f) {
    const double* a = &s.corners[3 * per * static_cast<std::size_t>(f)];
    return per == 2 ? closest_on_segment(y, a, a + 3) : closest_on_triangle(y, a, a + 3, a + 6);
  };
  const auto distance_to = [&y](const Closest& c) {
    const double r[3] = {y[0] - c.point[0], y[1] - c.point[1], y[2] - c.point[2]};
    return std::sqrt(dot(r, r));
  };
  // The nearest closest point, and every distinct closest point as near (y on a medial surface,
  // inside: the bisector of a polygon's corner, equally deep under its two sides; a point under
  // the edge between two rows of a tube's facets, equally near two sides' rims): the directions
  // to all of them are summed below, not whichever came first (that would tilt the force by the
  // corner's half angle: a polygonal punch centred on a corner, a tube on its side pushed
  // sideways). Each point once (an edge or corner is found from every facet that has it); one
  // pass, the list kept to those within `tie` of the nearest so far.
  struct Near {
    double point[3];
    double distance;
    std::size_t facet;
    bool interior;
  };
  constexpr int most = 16;
  Near listed[most];
  int distinct = 0;
  const double tie = 1e-12 * reach_;
  double best = 1e300;
  Closest nearest;
  std::size_t nearest_facet = 0;
  for (const int* f = begin; f != end; ++f) {
    if (!in_box(*f) || box_distance(*f) > best + tie) continue;
    const auto c = closest(*f);
    const double d = distance_to(c);
    if (d > best + tie) continue;
    const auto facet = static_cast<std::size_t>(*f);
    if (d < best) {
      best = d;
      nearest = c;
      nearest_facet = facet;
      int kept = 0;
      for (int i = 0; i < distinct; ++i)
        if (listed[i].distance <= best + tie) listed[kept++] = listed[i];
      distinct = kept;
    }
    bool again = false;
    for (int i = 0; i < distinct && !again; ++i) {
      const double e[3] = {c.point[0] - listed[i].point[0], c.point[1] - listed[i].point[1],
                           c.point[2] - listed[i].point[2]};
      again = dot(e, e) <= tie * tie;
    }
    if (!again && distinct < most)
      listed[distinct++] = {{c.point[0], c.point[1], c.point[2]}, d, facet, c.interior()};
  }
  // Farther than the capture depth the nearest facet may not be among those tested: no contact.
  if (!(best <= capture_)) return p;
  const double r[3] = {y[0] - nearest.point[0], y[1] - nearest.point[1], y[2] - nearest.point[2]};
  // The sign: the facet's plane in its interior, else the edge's or corner's pseudo-normal.
  const double* n = nearest.interior() ? pseudo_.face(nearest_facet)
                    : nearest.feature == Closest::Feature::edge
                        ? pseudo_.edge(nearest_facet, nearest.local)
                        : pseudo_.corner(nearest_facet, nearest.local);
  const double sign = dot(r, n) < 0 ? -1.0 : 1.0;
  double sum[3] = {0, 0, 0};
  for (int i = 0; i < distinct; ++i)
    for (int k = 0; k < 3; ++k)  // in a face's interior y - p is along its normal
      sum[k] += listed[i].interior ? pseudo_.face(listed[i].facet)[k] * sign * best
                                   : y[k] - listed[i].point[k];
  if (nearest.interior() && distinct <= 1) {  // the facet's plane (as an analytic face)
    const double* a = &s.corners[3 * per * nearest_facet];
    const double ra[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
    p.gap = dot(ra, n);
    for (int k = 0; k < 3; ++k) p.normal[k] = n[k];
    return p;
  }
  // An edge, a corner or a tie: the distance, signed as above; the force along y - p (the
  // distance's gradient: continuous across the facets' edges, outside and inside).
  p.gap = sign * best;
  const double size = std::sqrt(dot(sum, sum));
  if (best > 0 && size > 0) {
    for (int k = 0; k < 3; ++k) p.normal[k] = sign * sum[k] / size;
  } else {
    const double length = std::sqrt(dot(n, n));
    for (int k = 0; k < 3; ++k) p.normal[k] = length > 0 ? n[k] / length : 0.0;
  }
  return p;
}

Proximity mesh_proximity(const MeshSurface& mesh, const double* y) {
  return mesh.proximity(y);
}

}  // namespace efg::contact
