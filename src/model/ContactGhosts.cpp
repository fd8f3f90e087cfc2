#include "model/ContactGhosts.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>

#include "discretization/SmoothingFacets.hpp"

namespace efg {

bool acts_between_parts_implicitly(const Scene& scene, const ContactSpec& contact) {
  if (contact.target_parts.empty()) return false;
  return std::any_of(scene.stages.begin(), scene.stages.end(), [&](const StageSpec& st) {
    return st.driver == "implicit" && contact.stages.includes(st.name);
  });
}

std::vector<LocalIndex> contact_row_ghosts(const CommPtr& comm, const Model& model) {
  std::vector<std::string> parts;
  for (const auto& c : model.scene.contacts)
    if (acts_between_parts_implicitly(model.scene, c)) {
      parts.insert(parts.end(), c.parts.begin(), c.parts.end());
      parts.insert(parts.end(), c.target_parts.begin(), c.target_parts.end());
    }
  if (parts.empty()) return {};
  // A flag per mesh node (the mesh is on every rank already), raised by the owners of surface
  // particles for their rows' nodes, then the maximum over ranks.
  const auto nodes = model.mesh.node_count();
  std::vector<int> mine(nodes, 0), all(nodes, 0);
  for (const auto& part : model.parts) {
    if (std::find(parts.begin(), parts.end(), part.part->name) == parts.end()) continue;
    std::vector<char> on_surface(nodes, 0);
    for (const auto& [cell, side] : boundary_sides(model.mesh, part.part->blocks))
      for (auto n : model.mesh.side_node_indices(cell, side))
        on_surface[static_cast<std::size_t>(n)] = 1;
    const auto& rows = part.particle_values();
    for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
      if (!on_surface[static_cast<std::size_t>(part.cloud.mesh_node[j])]) continue;
      for (auto k = rows.offsets[j]; k < rows.offsets[j + 1]; ++k)
        mine[static_cast<std::size_t>(
            part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])])] = 1;
    }
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(nodes), mine.data(), all.data());
  std::vector<LocalIndex> ghosts;
  for (std::size_t n = 0; n < nodes; ++n)
    if (all[n] && model.partition.owner[n] != model.partition.rank)
      ghosts.push_back(static_cast<LocalIndex>(n));
  return ghosts;
}

}  // namespace efg
