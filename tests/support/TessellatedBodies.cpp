#include "support/TessellatedBodies.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace efg::test {

namespace {

using Point = std::array<double, 3>;

// Appends triangle a, b, c (counter-clockwise seen from outside) with its longest edge.
void add(RigidSurface& s, const Point& a, const Point& b, const Point& c) {
  double longest = 0;
  for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (p[k] - q[k]) * (p[k] - q[k]);
    longest = std::max(longest, std::sqrt(d2));
  }
  for (const auto* p : {&a, &b, &c}) s.corners.insert(s.corners.end(), p->begin(), p->end());
  s.reference_size.push_back(longest);
}

// A quadrilateral 0-1-2-3 (counter-clockwise from outside) cut along its 0-2 diagonal.
void add_quad(RigidSurface& s, const Point& p0, const Point& p1, const Point& p2, const Point& p3) {
  add(s, p0, p1, p2);
  add(s, p0, p2, p3);
}

RigidSurface empty_surface() {
  RigidSurface s;
  s.dim = 3;
  s.nodes_per_facet = 3;
  return s;
}

}  // namespace

RigidSurface tessellated_sphere(double r, int rings, int segments) {
  const double pi = std::acos(-1.0);
  auto s = empty_surface();
  const auto at = [&](int i, int j) {  // ring line i (0: north pole), meridian j
    const double theta = pi * i / rings, phi = 2.0 * pi * (j % segments) / segments;
    return Point{r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                 r * std::cos(theta)};
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      if (i == 0)
        add(s, at(0, 0), at(1, j), at(1, j + 1));
      else if (i == rings - 1)
        add(s, at(i, j), at(rings, 0), at(i, j + 1));
      else
        add_quad(s, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return s;
}

RigidSurface tessellated_mapped_cylinder(double r, double h, int n, int layers) {
  auto s = empty_surface();
  const auto disc = [&](int i, int j, double z) {  // node (i, j) of the square's n x n grid
    const double x = -1.0 + 2.0 * i / n, y = -1.0 + 2.0 * j / n;
    return Point{r * x * std::sqrt(1.0 - y * y / 2.0), r * y * std::sqrt(1.0 - x * x / 2.0), z};
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      add_quad(s, disc(i, j, h), disc(i + 1, j, h), disc(i + 1, j + 1, h), disc(i, j + 1, h));
      add_quad(s, disc(i, j, 0), disc(i, j + 1, 0), disc(i + 1, j + 1, 0), disc(i + 1, j, 0));
    }
  // The square's boundary, counter-clockwise about z: the rim's nodes.
  std::vector<std::array<int, 2>> rim;
  for (int i = 0; i < n; ++i) rim.push_back({i, 0});
  for (int j = 0; j < n; ++j) rim.push_back({n, j});
  for (int i = n; i > 0; --i) rim.push_back({i, n});
  for (int j = n; j > 0; --j) rim.push_back({0, j});
  const auto m = rim.size();
  for (std::size_t k = 0; k < m; ++k)
    for (int l = 0; l < layers; ++l) {
      const auto& a = rim[k];
      const auto& b = rim[(k + 1) % m];
      const double z0 = h * l / layers, z1 = h * (l + 1) / layers;
      add_quad(s, disc(a[0], a[1], z0), disc(b[0], b[1], z0), disc(b[0], b[1], z1),
               disc(a[0], a[1], z1));
    }
  return s;
}

RigidSurface tessellated_wedge(double apex, double l, double w, int fan) {
  auto s = empty_surface();
  const double t = l * std::tan(apex / 2.0);
  const Point v{0, 0, 0}, a1{0, w, 0}, b0{l, 0, t}, b1{l, w, t}, c0{l, 0, -t}, c1{l, w, -t};
  const Point centroid{2.0 * l / 3.0, w / 2.0, 0.0};
  // Each triangle turned to face away from the centroid (the prism is convex).
  const auto outward = [&](const Point& p, const Point& q, const Point& r) {
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double x[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    const double n[3] = {u[1] * x[2] - u[2] * x[1], u[2] * x[0] - u[0] * x[2],
                         u[0] * x[1] - u[1] * x[0]};
    double out = 0;
    for (int k = 0; k < 3; ++k) out += n[k] * (p[k] - centroid[k]);
    if (out > 0)
      add(s, p, q, r);
    else
      add(s, p, r, q);
  };
  // The upper side (v, b0, b1, a1): a fan at v over fan points along b0-b1, then (v, b1, a1).
  std::vector<Point> edge;
  for (int i = 0; i <= fan; ++i) edge.push_back({l, w * i / fan, t});
  for (int i = 0; i < fan; ++i) outward(v, edge[i], edge[i + 1]);
  outward(v, b1, a1);
  // The back (x = l) shares the fan's points on b0-b1 (no T-junctions): a fan from c0, then
  // (c0, c1, b1).
  for (int i = 0; i < fan; ++i) outward(c0, edge[i], edge[i + 1]);
  outward(c0, c1, b1);
  // The lower side (v, c0, c1, a1) cut along c0-a1: one triangle at v.
  outward(v, c0, a1);
  outward(c0, c1, a1);
  // The ends.
  outward(v, b0, c0);
  outward(a1, b1, c1);
  return s;
}

}  // namespace efg::test
