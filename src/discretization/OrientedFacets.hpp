// The boundary of a set of blocks as facets: the sides of their cells that no other cell of the
// blocks shares, as segments (2D) or triangles (3D; a quadrilateral side cut along its 0-2
// diagonal), their nodes ordered so that geometry/FacetNormal.hpp's normal points out of the
// blocks (checked against the cell's centroid). The surface of deformable parts for the contact
// between them (contact/SurfaceFacets) and of rigid bodies made of mesh blocks
// (model/RigidMeshBlocks).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct OrientedFacets {
  int nodes_per_facet = 2;             ///< 2 (segments) or 3 (triangles)
  std::vector<LocalIndex> nodes;       ///< mesh nodes, nodes_per_facet per facet, outward order
  std::vector<double> reference_size;  ///< longest edge of each facet
  /// Where each facet comes from: (cell, side, piece of the side), in the order listed.
  std::vector<std::array<std::size_t, 3>> origin;

  std::size_t count() const { return reference_size.size(); }
};

OrientedFacets oriented_boundary_facets(const BackgroundMesh& mesh,
                                        const std::vector<std::string>& blocks);

}  // namespace efg
