// Which facet of a deformable target a surface particle presses into, shared by the explicit
// (contact/SurfaceContact) and implicit (contact/ImplicitSurfaceContact) contacts between
// deformable parts; plain functions, no Trilinos.
//  - facet_capture_box: a facet's box in the current configuration grown by the region a
//    particle caught by it can be in: over the facet (within kOverTolerance of its size) and at
//    most its capture depth along its normal n, i.e. by capture |n_k| per axis, plus a margin.
//    A flat facet's box then stays thin in its plane and a bin lists a few facets.
//  - nodal_normals: a surface node's unit normal, the sum of its facets' normals scaled by
//    their length (2D) or twice their area (3D), normalized (the facing rule's own normal).
//  - choose_facet: the facet of the last accepted step while the particle still lies over it,
//    inside and not deeper than the facet's size (contact history, as node-to-segment codes
//    track their master segment); otherwise, among the facets facing the particle's own surface
//    (kFacing) that it lies over and is inside of, the one nearest along its normal.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "contact/FacetBins.hpp"
#include "contact/FacetProjection.hpp"

namespace efg::contact {

// A projection may fall this far (in facet coordinates) beyond a facet's edge and still count:
// a particle over the node shared by two facets belongs to one of them, and a particle on the
// line of an edge keeps its facet when round-off moves it a little past the edge.
constexpr double kOverTolerance = 0.01;
// Surfaces face each other when the candidate's normal and the facet's make more than about
// 100 degrees (n_c . n_f below -0.2). A corner particle (normal between its two faces) then
// meets a flush target end through the end face, not through the side it merely lies on; and a
// particle of a base just ahead of a block sliding over it (pressed a little into the base by
// the penalty) is not pushed out through the block's leading side, which would catch the block
// on the kerb.
constexpr double kFacing = -0.2;

/// Facet corners (count positions) grown as above into [lower, upper) (dim components each);
/// returns the box's largest edge before growing.
inline double facet_capture_box(const double (*corner)[3], int count, int dim, double capture,
                                double margin, double* lower, double* upper) {
  double normal[3];
  facet_normal(corner, dim, normal);
  const double length =
      std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  double edge = 0;
  for (int k = 0; k < dim; ++k) {
    double lo = corner[0][k], hi = lo;
    for (int a = 1; a < count; ++a) {
      lo = std::min(lo, corner[a][k]);
      hi = std::max(hi, corner[a][k]);
    }
    // (a degenerate facet, of no normal, grows by its capture depth every way)
    const double along = length > 0 ? std::abs(normal[k]) / length : 1.0;
    const double grow = capture * (along + kOverTolerance) + margin;
    lower[k] = lo - grow;
    upper[k] = hi + grow;
    edge = std::max(edge, hi - lo);
  }
  return edge;
}

/// facet: per node indices per facet; x: 3 per surface node; normal: 3 per node, out.
inline void nodal_normals(const std::vector<int>& facet, int per, const std::vector<double>& x,
                          int dim, std::vector<double>& normal) {
  const auto n_per = static_cast<std::size_t>(per);
  normal.assign(x.size(), 0.0);
  for (std::size_t k = 0; k * n_per < facet.size(); ++k) {
    double corner[3][3] = {}, n[3];
    for (std::size_t a = 0; a < n_per; ++a)
      for (std::size_t i = 0; i < 3; ++i)
        corner[a][i] = x[3 * static_cast<std::size_t>(facet[k * n_per + a]) + i];
    facet_normal(corner, dim, n);
    for (std::size_t a = 0; a < n_per; ++a)
      for (std::size_t i = 0; i < 3; ++i)
        normal[3 * static_cast<std::size_t>(facet[k * n_per + a]) + i] += n[i];
  }
  for (std::size_t node = 0; 3 * node < normal.size(); ++node) {
    double* n = &normal[3 * node];
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0)
      for (int i = 0; i < 3; ++i) n[i] /= len;
  }
}

/// x and n_own: the particle and its surface's unit normal there; facet_old: its facet of the
/// last accepted step (-1: none); corners(f, c): facet f's current corners into c;
/// reference_size[f]: facet f's size (its capture depth). Returns (-1, ..) when it presses into
/// none.
template <class Corners, class Sizes>
std::pair<int, FacetPoint> choose_facet(const double* x, const double* n_own, int facet_old,
                                        const FacetBins& bins, const Sizes& reference_size, int dim,
                                        const Corners& corners) {
  auto project = [&](int facet) {
    double corner[3][3] = {};
    corners(static_cast<std::size_t>(facet), corner);
    return project_on_facet(x, corner, dim, kOverTolerance);
  };
  auto pressing = [&](int facet, const FacetPoint& p) {
    return p.over && p.gap < 0 && -p.gap <= reference_size[static_cast<std::size_t>(facet)] &&
           p.normal[0] * n_own[0] + p.normal[1] * n_own[1] + p.normal[2] * n_own[2] < kFacing;
  };
  if (facet_old >= 0) {
    const auto p = project(facet_old);
    if (pressing(facet_old, p)) return {facet_old, p};
  }
  int best = -1;
  FacetPoint best_point;
  const auto [begin, end] = bins.near(x);
  for (const int* it = begin; it != end; ++it) {
    const auto p = project(*it);
    if (pressing(*it, p) && (best < 0 || std::abs(p.gap) < std::abs(best_point.gap))) {
      best = *it;
      best_point = p;
    }
  }
  return {best, best_point};
}

}  // namespace efg::contact
