// The signed distance to rigid bodies made of facets (contact/MeshSurface) against the analytic
// shapes they tessellate: a sphere by latitude and longitude, and the reported impactor's
// geometry - a cylinder whose ends are discs mapped from a square (slivers along the rim at the
// square's corners, a rim of unevenly spaced nodes). Points at every corner, edge midpoint and
// facet centroid, moved along the analytic normal outward and inward, and sideways:
// - the sign is the analytic shape's wherever the analytic distance exceeds the tessellation's
//   chord error delta (the facets are inscribed: the faceted body lies inside the analytic one,
//   within delta of its surface), out to twice the capture depth outside;
// - within the capture depth the distance is the analytic one within delta;
// - the normal is within the facet angle of the analytic normal (the largest angle between a
//   facet's normal and the analytic normal at its corners) and that of the closest analytic
//   point seen from y (a point off a corner sees the corner, not the face beyond it).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "contact/MeshSurface.hpp"
#include "support/TessellatedBodies.hpp"

namespace {

using efg::RigidSurface;
using efg::contact::MeshSurface;
using Point = std::array<double, 3>;

struct Analytic {
  double distance = 0;  ///< signed, negative inside
  Point normal{};       ///< outward unit normal of the closest surface point
};

double norm(const Point& a) {
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

double angle(const double* a, const Point& b) {
  const double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
                   std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) / norm(b);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

Point corner(const RigidSurface& s, std::size_t f, int a) {
  const double* p = &s.corners[9 * f + 3 * static_cast<std::size_t>(a)];
  return {p[0], p[1], p[2]};
}

// The largest angle between a facet's normal and the analytic normal at its corners.
double largest_facet_angle(const RigidSurface& s,
                           const std::function<Analytic(const Point&)>& shape) {
  double largest = 0;
  for (std::size_t f = 0; f < s.count(); ++f) {
    const auto a = corner(s, f, 0), b = corner(s, f, 1), c = corner(s, f, 2);
    const double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                         (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                         (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    for (const auto& p : {a, b, c}) largest = std::max(largest, angle(n, shape(p).normal));
  }
  return largest;
}

double median_size(const RigidSurface& s) {
  auto sizes = s.reference_size;
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<long>(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

// The analytic normal holds within 2 delta of y (to half the bound): y is off the medial
// surfaces, where the closest point jumps (inside a cylinder near the bisector of its rim).
bool steady(const std::function<Analytic(const Point&)>& shape, const Point& y, double delta,
            double bound) {
  const auto n = shape(y).normal;
  for (int k = 0; k < 3; ++k)
    for (double step : {-2.0 * delta, 2.0 * delta}) {
      Point z = y;
      z[k] += step;
      if (angle(shape(z).normal.data(), n) > bound / 2) return false;
    }
  return true;
}

struct Tally {
  int points = 0, wrong_sign = 0, far_distance = 0, tilted_normal = 0;
};

// Every facet's corners, edge midpoints and centroid, moved by t along the analytic normal and
// by s sideways (along the facet's first edge), each checked.
Tally check(const RigidSurface& s, const std::function<Analytic(const Point&)>& shape, double delta,
            double facet_angle_bound) {
  const MeshSurface mesh(std::make_shared<const RigidSurface>(s));
  const double capture = median_size(s);
  Tally tally;
  const double offsets[] = {-0.8, -0.4, -0.1, 0.02, 0.1, 0.4, 0.8, 1.3, 2.0};
  const double sideways[] = {0.0, 0.05, -0.2};
  for (std::size_t f = 0; f < s.count(); ++f) {
    const auto a = corner(s, f, 0), b = corner(s, f, 1), c = corner(s, f, 2);
    std::vector<Point> seeds = {a, b, c};
    for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      seeds.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    seeds.push_back({(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3});
    Point edge{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double len = norm(edge);
    for (auto& e : edge) e /= len;
    for (const auto& seed : seeds)
      for (double t : offsets)
        for (double side : sideways) {
          const auto n = shape(seed).normal;
          Point y{};
          for (int k = 0; k < 3; ++k)
            y[k] = seed[k] + t * capture * n[k] + side * capture * edge[k];
          const auto exact = shape(y);
          if (std::abs(exact.distance) <= delta) continue;  // within the chord error: either sign
          if (exact.distance < -0.9 * capture) continue;    // deeper than the capture depth
          const auto got = mesh.proximity(y.data());
          ++tally.points;
          if ((got.gap < 0) != (exact.distance < 0)) ++tally.wrong_sign;
          if (std::abs(exact.distance) > 0.9 * capture) continue;
          if (std::abs(got.gap - exact.distance) > delta * (1 + 1e-9)) ++tally.far_distance;
          // The closest analytic point seen from y (its normal) and the faceted surface's are up
          // to delta apart: seen from |d|, their directions differ by up to asin(delta / |d|).
          // Skipped where the analytic normal turns within delta of y (a medial surface).
          if (!steady(shape, y, delta, facet_angle_bound)) continue;
          const double seen = std::asin(std::min(1.0, delta / std::abs(exact.distance)));
          if (angle(got.normal, exact.normal) > facet_angle_bound + seen) ++tally.tilted_normal;
        }
  }
  return tally;
}

Analytic sphere(const Point& y, double r) {
  const double d = norm(y);
  return {d - r, {y[0] / d, y[1] / d, y[2] / d}};
}

// The solid cylinder x^2 + y^2 <= r^2, 0 <= z <= h: outside, the distance to its rim or faces;
// inside, to the nearest of its side and ends.
Analytic cylinder(const Point& y, double r, double h) {
  const double rho = std::hypot(y[0], y[1]);
  const Point radial{y[0] / rho, y[1] / rho, 0.0};
  const double dr = rho - r, dz = std::max(-y[2], y[2] - h);
  const double up = y[2] > h / 2 ? 1.0 : -1.0;
  if (dr > 0 || dz > 0) {
    const double pr = std::max(dr, 0.0), pz = std::max(dz, 0.0), d = std::hypot(pr, pz);
    return {d, {pr * radial[0] / d, pr * radial[1] / d, up * pz / d}};
  }
  if (dr > dz) return {dr, radial};
  return {dz, {0.0, 0.0, up}};
}

TEST(MeshSurfaceSign, SphereOfFacetsAgainstTheAnalyticSphere) {
  const double r = 1.0;
  const auto s = efg::test::tessellated_sphere(r, 12, 24);
  // Chord error: the largest depth of a facet's plane below the sphere (its circumcircle's sag).
  double delta = 0;
  for (std::size_t f = 0; f < s.count(); ++f) {
    const auto a = corner(s, f, 0), b = corner(s, f, 1), c = corner(s, f, 2);
    const Point n{(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                  (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                  (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
    delta = std::max(delta, r - (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / norm(n));
  }
  const auto shape = [r](const Point& y) { return sphere(y, r); };
  const auto tally = check(s, shape, delta, largest_facet_angle(s, shape));
  EXPECT_GT(tally.points, 10000);
  EXPECT_EQ(tally.wrong_sign, 0) << tally.points << " points";
  EXPECT_EQ(tally.far_distance, 0);
  EXPECT_EQ(tally.tilted_normal, 0);
}

TEST(MeshSurfaceSign, CylinderWithMappedDiscEndsAgainstTheAnalyticCylinder) {
  const double r = 40.0, h = 10.0;  // the reported impactor's cap, in mm
  const auto s = efg::test::tessellated_mapped_cylinder(r, h, 4, 1);
  // Chord error: the largest sag r (1 - cos(dtheta / 2)) of the rim's chords.
  std::vector<double> theta;
  for (std::size_t f = 0; f < s.count(); ++f)
    for (int a = 0; a < 3; ++a) {
      const auto p = corner(s, f, a);
      if (std::abs(std::hypot(p[0], p[1]) - r) < 1e-9 * r) theta.push_back(std::atan2(p[1], p[0]));
    }
  std::sort(theta.begin(), theta.end());
  theta.erase(std::unique(theta.begin(), theta.end(),
                          [](double x, double y) { return std::abs(x - y) < 1e-12; }),
              theta.end());
  double widest = theta.front() + 2.0 * std::acos(-1.0) - theta.back();
  for (std::size_t k = 1; k < theta.size(); ++k) widest = std::max(widest, theta[k] - theta[k - 1]);
  const double delta = r * (1.0 - std::cos(widest / 2.0));
  const auto shape = [r, h](const Point& y) { return cylinder(y, r, h); };
  // The facet angle: the side facets' normals and the radial directions at their corners (the
  // ends are flat) differ by up to half the widest chord's angle.
  const auto tally = check(s, shape, delta, widest / 2.0);
  EXPECT_GT(tally.points, 5000);
  EXPECT_EQ(tally.wrong_sign, 0) << tally.points << " points";
  EXPECT_EQ(tally.far_distance, 0);
  EXPECT_EQ(tally.tilted_normal, 0);
}

TEST(MeshSurfaceSign, SharpCornerSignedByAngleWeights) {
  // A 30-degree wedge whose corner at the origin has 9 triangles of its upper side (90 degrees
  // in all), one of its lower side (90) and one of its end (30). Points off that corner along
  // the lower side's normal, tilted slightly towards the upper side's and the end's normals,
  // lie in the corner's Voronoi region outside: their closest point is the corner. With equal
  // weights the pseudo-normal is 9 n_up + n_low + n_end, and (y - p) . it ~ 1 - 9 cos(30) < 0:
  // judged inside. The angle-weighted one, pi/2 n_up + pi/2 n_low + pi/6 n_end, signs them
  // outside (Baerentzen & Aanaes 2005, Theorem 1).
  const double pi = std::acos(-1.0), apex = pi / 6.0;
  const auto s = efg::test::tessellated_wedge(apex, 1.0, 1.0, 8);
  const MeshSurface mesh(std::make_shared<const RigidSurface>(s));
  const Point up{-std::sin(apex / 2), 0, std::cos(apex / 2)};
  const Point low{-std::sin(apex / 2), 0, -std::cos(apex / 2)};
  const Point end{0, -1, 0};
  int points = 0;
  for (double d : {0.01, 0.05, 0.2})
    for (double tilt : {0.05, 0.2, 0.5}) {
      Point y{};
      for (int k = 0; k < 3; ++k) y[k] = d * (low[k] + tilt * (up[k] + end[k]));
      const auto p = mesh.proximity(y.data());
      EXPECT_GT(p.gap, 0.0) << "outside at (" << y[0] << ", " << y[1] << ", " << y[2] << ")";
      EXPECT_NEAR(p.gap, norm(y), 1e-12);  // the corner is its closest point
      // and inside, under the lower side near the corner (closest point on that side)
      for (int k = 0; k < 3; ++k) y[k] = -d * 0.1 * low[k] + d * 0.5 * (Point{1, 0.5, 0}[k]);
      EXPECT_LT(mesh.proximity(y.data()).gap, 0.0);
      points += 2;
    }
  EXPECT_EQ(points, 18);
}

TEST(MeshSurfaceSign, ForceDirectionContinuousAcrossFacetEdges) {
  // Around the mapped-disc cylinder's side at 2 outside its radius, mid-height, in 7,200 steps:
  // the gap is a distance (1-Lipschitz: it changes by at most the step's length (R + d) dtheta)
  // and the normal turns smoothly - beside a facet its normal, over an edge (y - p) / |y - p|,
  // which turns at (R + d) / d times the sweep's rate at distance d from the edge. A normal that
  // jumped at an edge (the nearest facet's own, say) would turn by the edge's angle at once.
  const double r = 40.0, h = 10.0, d = 2.0, pi = std::acos(-1.0);
  const auto s = efg::test::tessellated_mapped_cylinder(r, h, 4, 1);
  const MeshSurface mesh(std::make_shared<const RigidSurface>(s));
  const int steps = 7200;
  const double dtheta = 2.0 * pi / steps;
  double last_gap = 0, largest_turn = 0, largest_change = 0;
  Point last{};
  for (int i = 0; i <= steps; ++i) {
    const double theta = i * dtheta;
    const Point y{(r + d) * std::cos(theta), (r + d) * std::sin(theta), h / 2};
    const auto p = mesh.proximity(y.data());
    ASSERT_GT(p.gap, 0.0);
    if (i > 0) {
      largest_turn = std::max(largest_turn, angle(p.normal, last));
      largest_change = std::max(largest_change, std::abs(p.gap - last_gap));
    }
    last = {p.normal[0], p.normal[1], p.normal[2]};
    last_gap = p.gap;
  }
  EXPECT_LE(largest_change, (r + d) * dtheta * (1 + 1e-9));
  // at distance >= d from every edge (the gap stays >= d: the polygon is inscribed)
  EXPECT_LE(largest_turn, (r + d) / d * dtheta * (1 + 1e-6));
}

}  // namespace
