// The area of a surface particle that faces a rigid body, for the material rule of the explicit
// contact's stiffness (contact/ContactStiffness.hpp). A particle's share of its part's boundary
// counts every side it lies on: at an edge of a block both faces, at a corner three. A flat tool
// pressing one face then met edge particles with springs twice (corners three times) as stiff
// as their share of that face carries: they held the block's rim down and the middle rose
// into the tool, 30 % deeper than a uniform pressure gives (a foam block under a plate). Each
// side's share is kept as a vector a_s n_s (its measure over its nodes, x thickness in 2D, along
// its unit normal), and the facing area against the body's normal n is
//   A_J(n) = sum_s a_s |n_s . n|
// (the projection of the particle's surface on the contact plane): the share of the touched face
// alone for a flat tool, all of it for a tool that meets the particle along a side's normal.
// Its largest value over all n is bounded by |c|, c_i = sum_s a_s |n_s,i| (Cauchy-Schwarz; exact
// for a block's axis-aligned faces): the stable step's w^2 uses that bound.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "model/Model.hpp"

namespace efg {

using SideShares = std::vector<std::array<double, 3>>;  ///< a_s n_s of the sides at a node

/// Per mesh node of part p's boundary, its sides' shares a_s n_s (empty off the boundary).
std::vector<SideShares> part_side_shares(const Model& model, std::size_t p);

namespace contact {

/// A_J(n) = sum_s a_s |n_s . n|.
inline double facing_area(const SideShares& sides, const double* n) {
  double area = 0;
  for (const auto& a : sides) area += std::abs(a[0] * n[0] + a[1] * n[1] + a[2] * n[2]);
  return area;
}

/// max over unit n of A_J(n) <= |c|, c_i = sum_s |a_s,i|.
inline double largest_facing_area(const SideShares& sides) {
  double c[3] = {0, 0, 0};
  for (const auto& a : sides)
    for (std::size_t i = 0; i < 3; ++i) c[i] += std::abs(a[i]);
  return std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
}

}  // namespace contact
}  // namespace efg
