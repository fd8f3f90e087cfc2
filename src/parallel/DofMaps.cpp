#include "parallel/DofMaps.hpp"

#include <Teuchos_OrdinalTraits.hpp>

namespace efg {
namespace {

Teuchos::RCP<const Map> map_of(const CommPtr& comm, const std::vector<LocalIndex>& first,
                               const std::vector<LocalIndex>& second, int per_node,
                               const GlobalNumbering& numbering,
                               const std::vector<GlobalIndex>& remote = {}) {
  std::vector<GlobalOrdinal> gids;
  gids.reserve((first.size() + second.size()) * static_cast<std::size_t>(per_node));
  for (const auto* list : {&first, &second})
    for (auto node : *list)
      for (int c = 0; c < per_node; ++c)
        gids.push_back(
            static_cast<GlobalOrdinal>(
                numbering.nodes.empty() ? node : numbering.nodes[static_cast<std::size_t>(node)]) *
                per_node +
            c);
  for (auto node : remote)
    for (int c = 0; c < per_node; ++c)
      gids.push_back(static_cast<GlobalOrdinal>(node) * per_node + c);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return Teuchos::rcp(new Map(
      invalid, Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), static_cast<int>(gids.size())),
      0, comm));
}

}  // namespace

DofMaps make_dof_maps(const CommPtr& comm, const NodePartition& partition, int dofs_per_node,
                      const GlobalNumbering& numbering) {
  const std::vector<LocalIndex> none;
  DofMaps maps;
  maps.dofs_per_node = dofs_per_node;
  maps.owned_nodes = map_of(comm, partition.owned, none, 1, numbering);
  maps.overlap_nodes =
      map_of(comm, partition.owned, partition.ghosts, 1, numbering, partition.remote_ghosts);
  maps.owned_dofs = map_of(comm, partition.owned, none, dofs_per_node, numbering);
  maps.overlap_dofs = map_of(comm, partition.owned, partition.ghosts, dofs_per_node, numbering,
                             partition.remote_ghosts);
  return maps;
}

}  // namespace efg
