#include "model/NodeSetSize.hpp"

#include <Teuchos_CommHelpers.hpp>

namespace efg {

std::size_t owned_entries_over_ranks(const Model& model, const NodeSet& set) {
  long long mine = 0, all = 0;
  for (auto n : set.nodes)
    if (model.partition.owner[static_cast<std::size_t>(n)] == model.partition.rank) ++mine;
  Teuchos::reduceAll(*model.maps.owned_nodes->getComm(), Teuchos::REDUCE_SUM, mine,
                     Teuchos::outArg(all));
  return static_cast<std::size_t>(all);
}

}  // namespace efg
