#include "model/ContactGhosts.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>

#include "discretization/SmoothingFacets.hpp"
#include "parallel/Exchange.hpp"

namespace efg {

bool acts_between_parts_implicitly(const Scene& scene, const ContactSpec& contact) {
  if (contact.target_parts.empty()) return false;
  return std::any_of(scene.stages.begin(), scene.stages.end(), [&](const StageSpec& st) {
    return st.driver == "implicit" && contact.stages.includes(st.name);
  });
}

namespace {

/// Calls f(row node) for the row nodes of this rank's owned surface particles of `parts`. On a
/// rank's part of a mesh read in slices the part's boundary sides found locally are exact for the
/// owned nodes: every cell around an owned node, and every cell sharing a side with one, is in
/// the part.
template <class F>
void for_each_owned_row_node(const Model& model, const std::vector<std::string>& parts, F&& f) {
  const auto nodes = model.mesh.node_count();
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
        f(part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])]);
    }
  }
}

}  // namespace

ContactRowGhosts contact_row_ghosts(const CommPtr& comm, const Model& model) {
  std::vector<std::string> parts;
  for (const auto& c : model.scene.contacts)
    if (acts_between_parts_implicitly(model.scene, c)) {
      parts.insert(parts.end(), c.parts.begin(), c.parts.end());
      parts.insert(parts.end(), c.target_parts.begin(), c.target_parts.end());
    }
  ContactRowGhosts ghosts;
  if (parts.empty()) return ghosts;
  const auto& mesh = model.mesh;
  const auto nodes = mesh.node_count();
  if (mesh.is_part()) {
    // The row nodes' whole-mesh indices from every rank (a band around the surfaces).
    std::vector<GlobalIndex> mine;
    for_each_owned_row_node(model, parts,
                            [&](LocalIndex n) { mine.push_back(mesh.global_node(n)); });
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    auto all = all_gather(comm, mine);
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    for (auto g : all) {
      const auto n = mesh.node_of(g);
      if (n < 0)
        ghosts.remote.push_back(g);  // owned elsewhere: this part holds every owned node
      else if (model.partition.owner[static_cast<std::size_t>(n)] != model.partition.rank)
        ghosts.held.push_back(n);
    }
    return ghosts;
  }
  // A flag per mesh node (the mesh is on every rank already), raised by the owners of surface
  // particles for their rows' nodes, then the maximum over ranks.
  std::vector<int> mine(nodes, 0), all(nodes, 0);
  for_each_owned_row_node(model, parts,
                          [&](LocalIndex n) { mine[static_cast<std::size_t>(n)] = 1; });
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(nodes), mine.data(), all.data());
  for (std::size_t n = 0; n < nodes; ++n)
    if (all[n] && model.partition.owner[n] != model.partition.rank)
      ghosts.held.push_back(static_cast<LocalIndex>(n));
  return ghosts;
}

}  // namespace efg
