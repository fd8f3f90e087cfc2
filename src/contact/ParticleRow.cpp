#include "contact/ParticleRow.hpp"

#include "discretization/SmoothingFacets.hpp"

namespace efg {

ParticleRow particle_row(const ModelOperators& ops, std::size_t p, std::size_t j) {
  const auto& part = ops.model().parts[p];
  ParticleRow row;
  for (int k = 0; k < part.cloud.dimension; ++k)
    row.X[static_cast<std::size_t>(k)] = part.cloud.x(j)[k];
  for (auto k = part.particle_values().offsets[j]; k < part.particle_values().offsets[j + 1]; ++k) {
    row.nodes.push_back(
        ops.solid().overlap_node(p)[static_cast<std::size_t>(part.particle_values().particles[k])]);
    row.phi.push_back(part.particle_values().values[k]);
  }
  return row;
}

std::vector<char> surface_nodes(const Model& model, std::size_t p) {
  const auto& mesh = model.mesh;
  std::vector<char> on_surface(mesh.node_count(), 0);
  for (const auto& [cell, side] : boundary_sides(mesh, model.parts[p].part->blocks))
    for (auto n : mesh.side_node_indices(cell, side)) on_surface[static_cast<std::size_t>(n)] = 1;
  return on_surface;
}

}  // namespace efg
