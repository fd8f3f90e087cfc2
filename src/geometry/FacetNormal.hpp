// The normal of a surface facet scaled by its size (plain function, no Trilinos): a segment's
// (dy, -dx) (its length) in 2D, a triangle's (b - a) x (c - a) (twice its area) in 3D. With the
// facets' nodes ordered so that it points out of the body, it is the outward normal of the
// contact facets (contact/FacetProjection.hpp) and of rigid mesh surfaces. And a facet's
// longest edge, its size.
#pragma once

#include <algorithm>
#include <cmath>

namespace efg {

/// node: 2 or 3 positions, 3 components each (z = 0 in 2D); m: the scaled normal. T is double
/// or a forward-AD number (the implicit contact between deformable parts differentiates it).
template <class T>
inline void facet_normal(const T (*node)[3], int dim, T* m) {
  const T ab[3] = {node[1][0] - node[0][0], node[1][1] - node[0][1], node[1][2] - node[0][2]};
  if (dim == 2) {
    m[0] = ab[1];
    m[1] = -ab[0];
    m[2] = T(0.0);
    return;
  }
  const T ac[3] = {node[2][0] - node[0][0], node[2][1] - node[0][1], node[2][2] - node[0][2]};
  m[0] = ab[1] * ac[2] - ab[2] * ac[1];
  m[1] = ab[2] * ac[0] - ab[0] * ac[2];
  m[2] = ab[0] * ac[1] - ab[1] * ac[0];
}

/// The longest edge of a facet of `count` corners (2 or 3 positions, 3 components each): its
/// size, the contact's capture depth.
inline double longest_edge(const double (*node)[3], int count) {
  double longest = 0;
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b) {
      double len2 = 0;
      for (int k = 0; k < 3; ++k) len2 += (node[a][k] - node[b][k]) * (node[a][k] - node[b][k]);
      longest = std::max(longest, std::sqrt(len2));
    }
  return longest;
}

}  // namespace efg
