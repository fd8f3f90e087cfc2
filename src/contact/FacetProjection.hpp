// The closest point of a surface facet to a particle, a plain function for the contact between
// deformable parts (no Trilinos). A facet is a segment (2D) or a triangle (3D) of a part's
// boundary in the current configuration, its nodes ordered so that the normal below points out
// of the part: 2D n = (b - a)^perp = (dy, -dx) / |b - a|, 3D n = (b - a) x (c - a) / |...|.
// The particle x is projected on the facet's line or plane: p = x - ((x - a) . n) n, with the
// facet coordinates w (barycentric, summing to one). It counts as over the facet when no w is
// below -tolerance; the signed gap is g = (x - a) . n (negative inside the part), and the
// weights that spread a force over the facet's nodes are w clipped to [0, 1] and rescaled to
// sum to one (so the nodes receive exactly the force: momentum is kept).
#pragma once

#include <cmath>

#include "geometry/FacetNormal.hpp"

namespace efg::contact {

using ::efg::facet_normal;  // geometry/FacetNormal.hpp

/// T: double, or a forward-AD number (contact/PairPenalty.hpp differentiates the projection).
template <class T>
struct FacetPointOf {
  bool over = false;  ///< the projection falls on the facet (within the tolerance)
  T gap = 0;          ///< signed distance along the outward normal
  T normal[3] = {0, 0, 0};
  T weight[3] = {0, 0, 0};  ///< of the facet's nodes, clipped, summing to one
};
using FacetPoint = FacetPointOf<double>;

/// x: the particle; nodes: 2 (2D) or 3 (3D) node positions, 3 components each (z = 0 in 2D).
template <class T>
inline FacetPointOf<T> project_on_facet(const T* x, const T (*node)[3], int dim, double tolerance) {
  using std::sqrt;
  FacetPointOf<T> f;
  const T* a = node[0];
  const T ab[3] = {node[1][0] - a[0], node[1][1] - a[1], node[1][2] - a[2]};
  const T ax[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
  T m[3], w[3] = {0, 0, 0};
  facet_normal(node, dim, m);
  const T size2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
  if (!(size2 > 0)) return f;
  const T size = sqrt(size2);
  for (int k = 0; k < 3; ++k) f.normal[k] = m[k] / size;
  const int count = dim == 2 ? 2 : 3;
  if (dim == 2) {
    const T t = (ax[0] * ab[0] + ax[1] * ab[1]) / size2;  // |ab|^2 = |m|^2 for a segment
    w[0] = 1.0 - t;
    w[1] = t;
  } else {
    // Barycentric coordinates of the projection: the sub-areas (x-a) x ac and ab x (x-a)
    // against m (the projection's normal part drops out of the dot products with m).
    const T ac[3] = {node[2][0] - a[0], node[2][1] - a[1], node[2][2] - a[2]};
    const T u[3] = {ax[1] * ac[2] - ax[2] * ac[1], ax[2] * ac[0] - ax[0] * ac[2],
                    ax[0] * ac[1] - ax[1] * ac[0]};
    const T v[3] = {ab[1] * ax[2] - ab[2] * ax[1], ab[2] * ax[0] - ab[0] * ax[2],
                    ab[0] * ax[1] - ab[1] * ax[0]};
    w[1] = (u[0] * m[0] + u[1] * m[1] + u[2] * m[2]) / size2;
    w[2] = (v[0] * m[0] + v[1] * m[1] + v[2] * m[2]) / size2;
    w[0] = 1.0 - w[1] - w[2];
  }
  f.gap = ax[0] * f.normal[0] + ax[1] * f.normal[1] + ax[2] * f.normal[2];
  f.over = true;
  T sum = 0;
  for (int k = 0; k < count; ++k) {
    if (w[k] < -tolerance) f.over = false;
    // clipped to [0, 1] (a clipped weight is a constant: no derivative)
    f.weight[k] = w[k] < 0.0 ? T(0.0) : (w[k] > 1.0 ? T(1.0) : w[k]);
    sum += f.weight[k];
  }
  for (int k = 0; k < count; ++k) f.weight[k] /= sum;
  return f;
}

}  // namespace efg::contact
