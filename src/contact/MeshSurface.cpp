#include "contact/MeshSurface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/FacetNormal.hpp"

namespace efg::contact {

namespace {

struct Closest {
  double point[3] = {0, 0, 0};
  bool interior = false;  ///< strictly inside the segment or triangle
};

double dot(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The closest point of segment a-b to y.
Closest closest_on_segment(const double* y, const double* a, const double* b) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ay[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(ay, ab) / len2 : 0.0;
  Closest c;
  c.interior = t > 0 && t < 1;
  t = std::clamp(t, 0.0, 1.0);
  for (int k = 0; k < 3; ++k) c.point[k] = a[k] + t * ab[k];
  return c;
}

// The closest point of triangle a, b, c to y (Ericson, Real-Time Collision Detection, 2005,
// sec. 5.1.5: the Voronoi regions of the corners and edges, else the face).
Closest closest_on_triangle(const double* y, const double* a, const double* b, const double* c) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ay[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
  const double d1 = dot(ab, ay), d2 = dot(ac, ay);
  Closest out;
  const auto at = [&out](const double* p) {
    for (int k = 0; k < 3; ++k) out.point[k] = p[k];
    return out;
  };
  if (d1 <= 0 && d2 <= 0) return at(a);
  const double by[3] = {y[0] - b[0], y[1] - b[1], y[2] - b[2]};
  const double d3 = dot(ab, by), d4 = dot(ac, by);
  if (d3 >= 0 && d4 <= d3) return at(b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return closest_on_segment(y, a, b);
  const double cy[3] = {y[0] - c[0], y[1] - c[1], y[2] - c[2]};
  const double d5 = dot(ab, cy), d6 = dot(ac, cy);
  if (d6 >= 0 && d5 <= d6) return at(c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return closest_on_segment(y, a, c);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return closest_on_segment(y, b, c);
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  for (int k = 0; k < 3; ++k) out.point[k] = a[k] + ab[k] * v + ac[k] * w;
  out.interior = true;
  return out;
}

}  // namespace

MeshSurface::MeshSurface(std::shared_ptr<const RigidSurface> surface)
    : surface_(std::move(surface)) {
  const auto& s = *surface_;
  const auto dim = static_cast<std::size_t>(s.dim);
  const auto per = static_cast<std::size_t>(s.nodes_per_facet);
  for (double h : s.reference_size) reach_ = std::max(reach_, h);
  // Each facet's box grown by its own size (its capture depth), at most the median facet's;
  // bins of the median facet's size (a few large facets, e.g. a die's sides, must not widen
  // every bin: they are listed in each bin they overlap, which keeps the search exact whatever
  // the bin size).
  std::vector<double> sizes = s.reference_size;
  double median_size = 0;
  if (!sizes.empty()) {
    auto middle = sizes.begin() + static_cast<long>(sizes.size() / 2);
    std::nth_element(sizes.begin(), middle, sizes.end());
    median_size = *middle;
  }
  std::vector<double> lower(s.count() * dim), upper(s.count() * dim);
  for (std::size_t f = 0; f < s.count(); ++f) {
    const double grow = std::min(s.reference_size[f], median_size);
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
  double best = 1e300;
  Closest nearest;
  std::size_t nearest_facet = 0;
  for (const int* f = begin; f != end; ++f) {
    if (!in_box(*f) || box_distance(*f) >= best) continue;
    const auto c = closest(*f);
    const double d = distance_to(c);
    if (d < best) {
      best = d;
      nearest = c;
      nearest_facet = static_cast<std::size_t>(*f);
    }
  }
  if (!(best < 1e300)) return p;
  const auto unit_normal = [&](std::size_t f, double* n) {
    double corner[3][3] = {};
    for (std::size_t a = 0; a < per; ++a)
      for (std::size_t k = 0; k < 3; ++k) corner[a][k] = s.corners[3 * (per * f + a) + k];
    facet_normal(corner, s.dim, n);
    const double size = std::sqrt(dot(n, n));
    for (int k = 0; k < 3; ++k) n[k] = size > 0 ? n[k] / size : 0.0;
  };
  // Facets as near as the nearest (a point on the bisector of a corner, inside: equally deep
  // under two facets' interiors): their normals summed decide, not whichever came first.
  const double tie = 1e-12 * reach_;
  double pseudo[3] = {0, 0, 0};
  int ties = 0;
  for (const int* f = begin; f != end; ++f) {
    if (!in_box(*f) || box_distance(*f) > best + tie || distance_to(closest(*f)) > best + tie)
      continue;
    double n[3];
    unit_normal(static_cast<std::size_t>(*f), n);
    for (int k = 0; k < 3; ++k) pseudo[k] += n[k];
    ++ties;
  }
  if (nearest.interior && ties == 1) {  // the facet's plane
    double n[3];
    unit_normal(nearest_facet, n);
    const double* a = &s.corners[3 * per * nearest_facet];
    const double r[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
    p.gap = dot(r, n);
    for (int k = 0; k < 3; ++k) p.normal[k] = n[k];
    return p;
  }
  // An edge or corner (the pseudo-normal of the facets that share the closest point signs the
  // distance; the normal points from that point), or a tie of interiors (the pseudo-normal).
  const double r[3] = {y[0] - nearest.point[0], y[1] - nearest.point[1], y[2] - nearest.point[2]};
  const double sign = dot(r, pseudo) < 0 ? -1.0 : 1.0;
  p.gap = sign * best;
  if (best > 0 && !nearest.interior) {
    for (int k = 0; k < 3; ++k) p.normal[k] = sign * r[k] / best;
  } else {
    const double size = std::sqrt(dot(pseudo, pseudo));
    for (int k = 0; k < 3; ++k) p.normal[k] = size > 0 ? pseudo[k] / size : 0.0;
  }
  return p;
}

Proximity mesh_proximity(const MeshSurface& mesh, const double* y) {
  return mesh.proximity(y);
}

}  // namespace efg::contact
