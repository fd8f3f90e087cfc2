#include "contact/SurfaceFacets.hpp"

#include <algorithm>

#include "discretization/OrientedFacets.hpp"
#include "parallel/Exchange.hpp"

namespace efg {
namespace {

// One facet by the whole mesh's numbers: where it comes from (cell, side, piece: the whole
// mesh's listing order), its nodes and its size.
struct Facet {
  std::array<std::size_t, 3> origin;
  std::array<GlobalIndex, 3> node;
  double size;
};

// Every rank's facets to every rank (each lists those whose lowest node it owns: the part's own
// boundary at its edge is no surface of the mesh, and its nodes are owned elsewhere).
std::vector<Facet> gathered(const Model& model, const std::vector<Facet>& mine) {
  auto all = all_gather(model.maps.owned_dofs->getComm(), mine);
  std::sort(all.begin(), all.end(),
            [](const Facet& a, const Facet& b) { return a.origin < b.origin; });
  return all;
}

}  // namespace

SurfaceFacets surface_facets(const Model& model, const std::vector<std::string>& parts) {
  const auto& mesh = model.mesh;
  std::vector<std::string> blocks;
  for (const auto& part : model.scene.parts)
    if (std::find(parts.begin(), parts.end(), part.name) != parts.end())
      blocks.insert(blocks.end(), part.blocks.begin(), part.blocks.end());
  const auto oriented = oriented_boundary_facets(mesh, blocks);
  const auto per = static_cast<std::size_t>(oriented.nodes_per_facet);
  std::vector<Facet> facets;
  for (std::size_t f = 0; f < oriented.count(); ++f) {
    Facet facet{oriented.origin[f], {0, 0, 0}, oriented.reference_size[f]};
    facet.origin[0] = static_cast<std::size_t>(mesh.global_cell(facet.origin[0]));
    auto lowest = oriented.nodes[f * per];
    for (std::size_t a = 0; a < per; ++a) {
      const auto n = oriented.nodes[f * per + a];
      facet.node[a] = mesh.global_node(static_cast<std::size_t>(n));
      lowest = std::min(lowest, n);
    }
    if (mesh.is_part() &&
        model.partition.owner[static_cast<std::size_t>(lowest)] != model.partition.rank)
      continue;
    facets.push_back(facet);
  }
  if (mesh.is_part()) facets = gathered(model, facets);
  SurfaceFacets s;
  s.nodes_per_facet = oriented.nodes_per_facet;
  for (const auto& facet : facets) {
    s.node_id.insert(s.node_id.end(), facet.node.begin(),
                     facet.node.begin() + static_cast<std::ptrdiff_t>(per));
    s.reference_size.push_back(facet.size);
  }
  std::sort(s.node_id.begin(), s.node_id.end());
  s.node_id.erase(std::unique(s.node_id.begin(), s.node_id.end()), s.node_id.end());
  for (const auto& facet : facets)
    for (std::size_t a = 0; a < per; ++a)
      s.facet.push_back(static_cast<int>(
          std::lower_bound(s.node_id.begin(), s.node_id.end(), facet.node[a]) - s.node_id.begin()));
  return s;
}

int surface_node_of(const SurfaceFacets& s, GlobalIndex node) {
  const auto it = std::lower_bound(s.node_id.begin(), s.node_id.end(), node);
  return it != s.node_id.end() && *it == node ? static_cast<int>(it - s.node_id.begin()) : -1;
}

}  // namespace efg
