// Which rank computes a background cell's terms (its Gauss points, its smoothed averages, its
// share of an error norm): the owner of the cell's lowest mesh node. Every rank decides alike
// from the replicated connectivity, so each cell is counted once over the ranks.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace efg {

/// The owning rank of the cell with nodes node[0 .. count) (owner: rank of every mesh node).
template <class Index>
int cell_owner(const Index* node, std::size_t count, const std::vector<int>& owner) {
  return owner[static_cast<std::size_t>(*std::min_element(node, node + count))];
}

}  // namespace efg
