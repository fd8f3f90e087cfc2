#include "mesh/BackgroundMesh.hpp"

#include <algorithm>
#include <stdexcept>

namespace efg {
namespace {
template <class Set>
const Set* find_named(const std::vector<Set>& sets, const std::string& name) {
  for (const auto& s : sets)
    if (s.name == name) return &s;
  return nullptr;
}
}  // namespace

LocalIndex BackgroundMesh::node_of(GlobalIndex id) const {
  if (!is_part())
    return id >= 0 && id < static_cast<GlobalIndex>(node_count()) ? static_cast<LocalIndex>(id)
                                                                  : -1;
  const auto it = std::lower_bound(global.nodes.begin(), global.nodes.end(), id);
  return it != global.nodes.end() && *it == id ? static_cast<LocalIndex>(it - global.nodes.begin())
                                               : -1;
}

std::size_t BackgroundMesh::cell_count() const {
  std::size_t n = 0;
  for (const auto& b : blocks) n += b.cell_count();
  return n;
}

const ElementBlock* BackgroundMesh::find_block(const std::string& name) const {
  return find_named(blocks, name);
}
const NodeSet* BackgroundMesh::find_node_set(const std::string& name) const {
  return find_named(node_sets, name);
}
const SideSet* BackgroundMesh::find_side_set(const std::string& name) const {
  return find_named(side_sets, name);
}

std::pair<const ElementBlock*, std::size_t> BackgroundMesh::locate_cell(std::size_t cell) const {
  for (const auto& b : blocks) {
    if (cell < b.cell_count()) return {&b, cell};
    cell -= b.cell_count();
  }
  throw std::out_of_range("cell index beyond the mesh's cell count");
}

std::vector<LocalIndex> BackgroundMesh::side_node_indices(std::size_t cell, int side) const {
  const auto [block, local] = locate_cell(cell);
  const auto n = static_cast<std::size_t>(cell_node_count(block->type));
  std::vector<LocalIndex> nodes;
  for (int a : cell_side_nodes(block->type, side))
    nodes.push_back(block->connectivity[local * n + static_cast<std::size_t>(a)]);
  return nodes;
}

}  // namespace efg
