// The closest point of a segment or triangle to a point, and which feature of it that point is
// on - the facet's interior, one of its edges or one of its corners (plain functions, no
// Trilinos). The feature decides how a rigid mesh surface signs the distance
// (contact/PseudoNormals.hpp): the facet's own normal in its interior, the pseudo-normal of the
// edge or corner otherwise (Baerentzen & Aanaes, IEEE TVCG 11(3), 2005).
#pragma once

#include <algorithm>

namespace efg::contact {

struct Closest {
  enum class Feature { face, edge, corner };
  double point[3] = {0, 0, 0};
  Feature feature = Feature::face;
  /// corner: its local index (0, 1, 2); edge: its first local corner, the edge going from it to
  /// the next corner (0-1, 1-2, 2-0 of a triangle; 0-1 of a segment).
  int local = 0;
  bool interior() const { return feature == Feature::face; }
};

namespace detail {
inline double dot3(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
}  // namespace detail

/// The closest point of segment a-b to y; i, j: the local indices of a and b in their facet;
/// `edge`: the segment is an edge of a triangle (else the whole facet, a 2D segment: its
/// interior is the face).
inline Closest closest_on_segment(const double* y, const double* a, const double* b, int i = 0,
                                  int j = 1, bool edge = false) {
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ay[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
  const double len2 = detail::dot3(ab, ab);
  double t = len2 > 0 ? detail::dot3(ay, ab) / len2 : 0.0;
  Closest c;
  if (t <= 0) {
    c.feature = Closest::Feature::corner;
    c.local = i;
    t = 0;
  } else if (t >= 1) {
    c.feature = Closest::Feature::corner;
    c.local = j;
    t = 1;
  } else {
    c.feature = edge ? Closest::Feature::edge : Closest::Feature::face;
    // The edge from corner i to the next one: 0-1, 1-2, 2-0 (a-c is the edge 2-0).
    c.local = (j == (i + 1) % 3) ? i : j;
  }
  for (int k = 0; k < 3; ++k) c.point[k] = a[k] + t * ab[k];
  return c;
}

/// The closest point of triangle a, b, c to y (Ericson, Real-Time Collision Detection, 2005,
/// sec. 5.1.5: the Voronoi regions of the corners and edges, else the face).
inline Closest closest_on_triangle(const double* y, const double* a, const double* b,
                                   const double* c) {
  using detail::dot3;
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double ay[3] = {y[0] - a[0], y[1] - a[1], y[2] - a[2]};
  const double d1 = dot3(ab, ay), d2 = dot3(ac, ay);
  Closest out;
  const auto at = [&out](const double* p, int local) {
    for (int k = 0; k < 3; ++k) out.point[k] = p[k];
    out.feature = Closest::Feature::corner;
    out.local = local;
    return out;
  };
  if (d1 <= 0 && d2 <= 0) return at(a, 0);
  const double by[3] = {y[0] - b[0], y[1] - b[1], y[2] - b[2]};
  const double d3 = dot3(ab, by), d4 = dot3(ac, by);
  if (d3 >= 0 && d4 <= d3) return at(b, 1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return closest_on_segment(y, a, b, 0, 1, true);
  const double cy[3] = {y[0] - c[0], y[1] - c[1], y[2] - c[2]};
  const double d5 = dot3(ab, cy), d6 = dot3(ac, cy);
  if (d6 >= 0 && d5 <= d6) return at(c, 2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return closest_on_segment(y, a, c, 0, 2, true);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return closest_on_segment(y, b, c, 1, 2, true);
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  for (int k = 0; k < 3; ++k) out.point[k] = a[k] + ab[k] * v + ac[k] * w;
  out.feature = Closest::Feature::face;
  return out;
}

}  // namespace efg::contact
