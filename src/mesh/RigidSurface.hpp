// The surface of a rigid body made of mesh blocks (model/RigidMeshBlocks), as the contact
// evaluates it (contact/MeshSurface): its boundary facets by their corners, outward ordered, in
// the reference configuration, and the volume, centroid and second moments of its cells (its
// mass from a density, the point its moments are taken about, its inertia). Plain data.
#pragma once

#include <array>
#include <vector>

namespace efg {

struct RigidSurface {
  int dim = 3;
  int nodes_per_facet = 3;             ///< 2 (segments, 2D) or 3 (triangles, 3D)
  std::vector<double> corners;         ///< 3 components per corner, nodes_per_facet per facet
  std::vector<double> reference_size;  ///< longest edge of each facet
  double volume = 0;                   ///< of the blocks' cells (2D: area)
  std::array<double, 3> centroid{};    ///< of the cells' volume (of a skin's area)
  /// Second moments of the cells' volume about the centroid, int (x_i - c_i)(x_j - c_j) dV:
  /// xx, yy, zz, xy, xz, yz (the inertia tensor per unit density, contact/RigidBodies).
  std::array<double, 6> second_moment{};

  std::size_t count() const { return reference_size.size(); }
};

}  // namespace efg
