// The boundary of deformable parts as contact facets: the sides of their cells that no other
// cell of the part shares, as segments (2D) or triangles (3D; a quadrilateral side is cut along
// its 0-2 diagonal), their nodes ordered so that the normal of contact/FacetProjection.hpp
// points out of the part (checked against the cell's centroid in the reference
// configuration). The same on every rank: on a rank's part of a distributed read (explicit
// contact) each rank lists the facets whose lowest node it owns and every rank gathers them all,
// ordered as the whole mesh lists them; a surface is far smaller than the volume.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"

namespace efg {

struct SurfaceFacets {
  int nodes_per_facet = 2;             ///< 2 (segments) or 3 (triangles)
  std::vector<GlobalIndex> node_id;    ///< surface node -> the whole mesh's node index, ascending
  std::vector<int> facet;              ///< nodes_per_facet surface nodes per facet
  std::vector<double> reference_size;  ///< longest edge of each facet, reference configuration

  std::size_t count() const { return reference_size.size(); }
};

/// The facets of the named parts' boundaries (collective on a part of a distributed read).
SurfaceFacets surface_facets(const Model& model, const std::vector<std::string>& parts);

/// The surface node of the whole mesh's node `node`, or -1 when it is not on the surface.
int surface_node_of(const SurfaceFacets& s, GlobalIndex node);

}  // namespace efg
