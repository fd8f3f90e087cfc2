#include "contact/BoundaryShares.hpp"

#include <algorithm>

#include "discretization/SmoothingFacets.hpp"
#include "mesh/SideMeasures.hpp"

namespace efg {

BoundaryShares boundary_shares(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                               double thickness) {
  BoundaryShares s;
  s.area.assign(mesh.node_count(), 0.0);
  s.size.assign(mesh.node_count(), 0.0);
  for (const auto& [cell, side] : boundary_sides(mesh, blocks)) {
    const auto nodes = mesh.side_node_indices(cell, side);
    const double share = side_measure(mesh, nodes) * thickness / static_cast<double>(nodes.size());
    const double h = side_longest_edge(mesh, nodes);
    for (auto n : nodes) {
      s.area[static_cast<std::size_t>(n)] += share;
      s.size[static_cast<std::size_t>(n)] = std::max(s.size[static_cast<std::size_t>(n)], h);
    }
  }
  return s;
}

BoundaryShares part_boundary_shares(const Model& model, std::size_t p) {
  const auto& part = *model.parts[p].part;
  return boundary_shares(model.mesh, part.blocks, model.mesh.dimension == 2 ? part.thickness : 1.0);
}

double part_youngs_modulus(const Model& model, std::size_t p) {
  const auto& part = *model.parts[p].part;
  return model.scene.find_material(part.material)->constants.at("youngs_modulus");
}

}  // namespace efg
