#include "contact/SurfaceFacets.hpp"

#include <algorithm>

#include "discretization/OrientedFacets.hpp"

namespace efg {

SurfaceFacets surface_facets(const Model& model, const std::vector<std::string>& parts) {
  const auto& mesh = model.mesh;
  std::vector<std::string> blocks;
  for (const auto& part : model.scene.parts)
    if (std::find(parts.begin(), parts.end(), part.name) != parts.end())
      blocks.insert(blocks.end(), part.blocks.begin(), part.blocks.end());
  const auto oriented = oriented_boundary_facets(mesh, blocks);
  SurfaceFacets s;
  s.nodes_per_facet = oriented.nodes_per_facet;
  s.reference_size = oriented.reference_size;
  std::vector<char> on_surface(mesh.node_count(), 0);
  for (auto n : oriented.nodes) on_surface[static_cast<std::size_t>(n)] = 1;
  std::vector<int> surface_index(mesh.node_count(), -1);
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    if (on_surface[n]) {
      surface_index[n] = static_cast<int>(s.mesh_node.size());
      s.mesh_node.push_back(static_cast<LocalIndex>(n));
    }
  for (auto n : oriented.nodes) s.facet.push_back(surface_index[static_cast<std::size_t>(n)]);
  return s;
}

}  // namespace efg
