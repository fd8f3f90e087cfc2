#include "discretization/CellSides.hpp"

#include <algorithm>

namespace efg {

std::vector<MatchedSide> matched_sides(const BackgroundMesh& mesh,
                                       const std::vector<std::size_t>& cells) {
  std::vector<MatchedSide> sides;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto [block, local] = mesh.locate_cell(cells[i]);
    (void)local;
    for (int s = 0; s < cell_side_count(block->type); ++s) {
      auto nodes = mesh.side_node_indices(cells[i], s);
      std::sort(nodes.begin(), nodes.end());
      MatchedSide side{{-1, -1, -1, -1}, static_cast<std::uint32_t>(i), s};
      std::copy(nodes.begin(), nodes.end(), side.key.begin());
      sides.push_back(side);
    }
  }
  std::sort(sides.begin(), sides.end(), [](const MatchedSide& a, const MatchedSide& b) {
    if (a.key != b.key) return a.key < b.key;
    return a.cell != b.cell ? a.cell < b.cell : a.side < b.side;
  });
  return sides;
}

std::vector<std::pair<std::size_t, int>> outer_sides(const BackgroundMesh& mesh,
                                                     const std::vector<std::size_t>& cells) {
  const auto sides = matched_sides(mesh, cells);
  std::vector<std::pair<std::size_t, int>> out;
  for_each_shared_key(sides, [&](std::size_t first, std::size_t last) {
    if (last - first == 1) out.emplace_back(cells[sides[first].cell], sides[first].side);
  });
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::size_t> cells_of_blocks(const BackgroundMesh& mesh,
                                         const std::vector<std::string>& blocks) {
  std::vector<std::size_t> cells;
  std::size_t global_cell = 0;
  for (const auto& b : mesh.blocks) {
    const bool in = std::find(blocks.begin(), blocks.end(), b.name) != blocks.end();
    for (std::size_t c = 0; c < b.cell_count(); ++c, ++global_cell)
      if (in) cells.push_back(global_cell);
  }
  return cells;
}

}  // namespace efg
