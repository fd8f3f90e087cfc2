// The boundary of deformable parts as contact facets: the sides of their cells that no other
// cell of the part shares, as segments (2D) or triangles (3D; a quadrilateral side is cut along
// its 0-2 diagonal), their nodes ordered so that the normal of contact/FacetProjection.hpp
// points out of the part (checked against the cell's centroid in the reference
// configuration). Built from the replicated mesh, identical on every rank.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"

namespace efg {

struct SurfaceFacets {
  int nodes_per_facet = 2;             ///< 2 (segments) or 3 (triangles)
  std::vector<LocalIndex> mesh_node;   ///< surface node -> mesh node, ascending
  std::vector<int> facet;              ///< nodes_per_facet surface nodes per facet
  std::vector<double> reference_size;  ///< longest edge of each facet, reference configuration

  std::size_t count() const { return reference_size.size(); }
};

/// The facets of the named parts' boundaries.
SurfaceFacets surface_facets(const Model& model, const std::vector<std::string>& parts);

}  // namespace efg
