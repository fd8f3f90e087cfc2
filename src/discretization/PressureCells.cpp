#include "discretization/PressureCells.hpp"

#include "discretization/CellSides.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace efg {
namespace {

const LocalIndex* cell_nodes(const BackgroundMesh& mesh, std::size_t cell, std::size_t& count) {
  const auto [block, local] = mesh.locate_cell(cell);
  count = static_cast<std::size_t>(cell_node_count(block->type));
  return &block->connectivity[local * count];
}

// Which cells share a side (face neighbours, by index into `cells`) and which mesh nodes lie on
// a side of one cell only (the part's boundary).
struct Adjacency {
  std::vector<std::vector<std::uint32_t>> neighbours;
  std::vector<char> on_boundary;
};

Adjacency adjacency(const BackgroundMesh& mesh, const std::vector<std::size_t>& cells) {
  const auto sides = matched_sides(mesh, cells);
  Adjacency out;
  out.neighbours.resize(cells.size());
  out.on_boundary.assign(mesh.node_count(), 0);
  for_each_shared_key(sides, [&](std::size_t first, std::size_t last) {
    if (last - first == 1) {
      for (auto n : sides[first].key)
        if (n >= 0) out.on_boundary[static_cast<std::size_t>(n)] = 1;
      return;
    }
    for (std::size_t a = first; a < last; ++a)
      for (std::size_t b = first; b < last; ++b)
        if (a != b) out.neighbours[sides[a].cell].push_back(sides[b].cell);
  });
  return out;
}

// Groups (lists of indices into `cells`) to PressureCells, ordered by their lowest cell.
PressureCells collect(const BackgroundMesh& mesh, const std::vector<std::size_t>& cells,
                      std::vector<std::vector<std::uint32_t>> groups) {
  for (auto& g : groups) std::sort(g.begin(), g.end());
  std::sort(groups.begin(), groups.end());
  PressureCells out;
  out.group.assign(mesh.cell_count(), PressureCells::none);
  for (const auto& g : groups) {
    for (auto i : g) {
      out.cells.push_back(cells[i]);
      out.group[cells[i]] = static_cast<std::uint32_t>(out.size());
    }
    out.offsets.push_back(out.cells.size());
  }
  return out;
}

}  // namespace

PressureCells single_cells(const BackgroundMesh& mesh, const PartSpec& part) {
  const auto cells = cells_of_blocks(mesh, part.blocks);
  std::vector<std::vector<std::uint32_t>> groups(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) groups[i] = {static_cast<std::uint32_t>(i)};
  return collect(mesh, cells, std::move(groups));
}

PressureCells pressure_cells(const BackgroundMesh& mesh, const PartSpec& part) {
  if (part.pressure_cells == PressureCellChoice::cell) return single_cells(mesh, part);
  const auto cells = cells_of_blocks(mesh, part.blocks);
  const auto adj = adjacency(mesh, cells);
  // The cells around each node.
  std::vector<std::size_t> start(mesh.node_count() + 1, 0);
  std::vector<std::uint32_t> around;
  for (auto c : cells) {
    std::size_t count = 0;
    const auto* node = cell_nodes(mesh, c, count);
    for (std::size_t a = 0; a < count; ++a) ++start[static_cast<std::size_t>(node[a]) + 1];
  }
  for (std::size_t n = 0; n < mesh.node_count(); ++n) start[n + 1] += start[n];
  around.resize(start.back());
  {
    auto fill = start;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      std::size_t count = 0;
      const auto* node = cell_nodes(mesh, cells[i], count);
      for (std::size_t a = 0; a < count; ++a)
        around[fill[static_cast<std::size_t>(node[a])]++] = static_cast<std::uint32_t>(i);
    }
  }
  constexpr auto unassigned = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> group_of(cells.size(), unassigned);
  std::vector<std::vector<std::uint32_t>> groups;
  // Vertex patches of interior nodes whose cells are all free, in node order.
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    if (adj.on_boundary[n] || start[n] == start[n + 1]) continue;
    bool free = true;
    for (auto k = start[n]; k < start[n + 1]; ++k) free = free && group_of[around[k]] == unassigned;
    if (!free) continue;
    std::vector<std::uint32_t> g(around.begin() + static_cast<std::ptrdiff_t>(start[n]),
                                 around.begin() + static_cast<std::ptrdiff_t>(start[n + 1]));
    for (auto i : g) group_of[i] = static_cast<std::uint32_t>(groups.size());
    groups.push_back(std::move(g));
  }
  // The smallest face-neighbouring group of cell i (unassigned when none).
  auto smallest_neighbour = [&](std::size_t i) {
    auto best = unassigned;
    for (auto j : adj.neighbours[i]) {
      const auto g = group_of[j];
      if (g != unassigned && g != group_of[i] &&
          (best == unassigned || groups[g].size() < groups[best].size() ||
           (groups[g].size() == groups[best].size() && g < best)))
        best = g;
    }
    return best;
  };
  // The rest join the smallest face-neighbouring group, repeatedly (a leftover row along an odd
  // count reaches a patch through its neighbours).
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (group_of[i] != unassigned) continue;
      const auto best = smallest_neighbour(i);
      if (best == unassigned) continue;
      group_of[i] = best;
      groups[best].push_back(static_cast<std::uint32_t>(i));
      changed = true;
    }
  }
  // Where no patch is near (a part one cell thick): each free cell with its free face
  // neighbours; a cell left alone joins its smallest neighbouring group.
  std::vector<std::uint32_t> alone;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (group_of[i] != unassigned) continue;
    std::vector<std::uint32_t> g{static_cast<std::uint32_t>(i)};
    for (auto j : adj.neighbours[i])
      if (group_of[j] == unassigned && std::find(g.begin(), g.end(), j) == g.end()) g.push_back(j);
    for (auto j : g) group_of[j] = static_cast<std::uint32_t>(groups.size());
    if (g.size() == 1) alone.push_back(static_cast<std::uint32_t>(i));
    groups.push_back(std::move(g));
  }
  for (auto i : alone) {
    const auto best = smallest_neighbour(i);
    if (best == unassigned) continue;  // an isolated cell keeps its own pressure
    groups[group_of[i]].clear();
    group_of[i] = best;
    groups[best].push_back(i);
  }
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                              [](const std::vector<std::uint32_t>& g) { return g.empty(); }),
               groups.end());
  return collect(mesh, cells, std::move(groups));
}

PressureCells groups_on_part(const BackgroundMesh& mesh, const PressureCells& whole) {
  PressureCells out;
  out.group.assign(mesh.cell_count(), PressureCells::none);
  const auto& here = mesh.global.cells;  // ascending: a cell's position is its local index
  std::vector<std::size_t> local;
  for (std::size_t g = 0; g < whole.size(); ++g) {
    local.clear();
    for (auto k = whole.offsets[g]; k < whole.offsets[g + 1]; ++k) {
      const auto id = static_cast<GlobalIndex>(whole.cells[k]);
      const auto it = std::lower_bound(here.begin(), here.end(), id);
      if (it == here.end() || *it != id) break;
      local.push_back(static_cast<std::size_t>(it - here.begin()));
    }
    if (local.size() != whole.offsets[g + 1] - whole.offsets[g]) continue;  // not all here
    for (auto c : local) {
      out.cells.push_back(c);
      out.group[c] = static_cast<std::uint32_t>(out.size());
    }
    out.offsets.push_back(out.cells.size());
  }
  return out;
}

std::vector<std::size_t> owned_groups(const BackgroundMesh& mesh, const PressureCells& groups,
                                      const std::vector<int>& owner, int rank) {
  std::vector<std::size_t> owned;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    auto lowest = std::numeric_limits<LocalIndex>::max();
    for (auto k = groups.offsets[g]; k < groups.offsets[g + 1]; ++k) {
      std::size_t count = 0;
      const auto* node = cell_nodes(mesh, groups.cells[k], count);
      lowest = std::min(lowest, *std::min_element(node, node + count));
    }
    if (owner[static_cast<std::size_t>(lowest)] == rank) owned.push_back(g);
  }
  return owned;
}

double largest_group_diameter(const BackgroundMesh& mesh, const PressureCells& groups) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  double largest = 0;
  std::vector<LocalIndex> nodes;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    nodes.clear();
    for (auto k = groups.offsets[g]; k < groups.offsets[g + 1]; ++k) {
      std::size_t count = 0;
      const auto* node = cell_nodes(mesh, groups.cells[k], count);
      nodes.insert(nodes.end(), node, node + count);
    }
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (std::size_t b = a + 1; b < nodes.size(); ++b) {
        double d2 = 0;
        for (std::size_t d = 0; d < dim; ++d) {
          const double dx = mesh.coordinates[static_cast<std::size_t>(nodes[a]) * dim + d] -
                            mesh.coordinates[static_cast<std::size_t>(nodes[b]) * dim + d];
          d2 += dx * dx;
        }
        largest = std::max(largest, d2);
      }
  }
  return std::sqrt(largest);
}

}  // namespace efg
