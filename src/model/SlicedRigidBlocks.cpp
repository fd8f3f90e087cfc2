#include "model/SlicedRigidBlocks.hpp"

#include <algorithm>

#include "core/Errors.hpp"
#include "mesh/MeshValidation.hpp"
#include "model/RigidMeshBlocks.hpp"
#include "parallel/Collective.hpp"
#include "parallel/Exchange.hpp"
#include "parallel/SliceLookup.hpp"

namespace efg {
namespace {

bool named(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The rigid blocks whole on every rank (their nodes numbered by position in `nodes`).
BackgroundMesh gather_rigid_blocks(const CommPtr& comm, const MeshSlice& slice,
                                   const std::vector<std::string>& names,
                                   std::vector<GlobalIndex>& nodes) {
  BackgroundMesh rigid;
  rigid.dimension = slice.dimension;
  rigid.source = slice.source;
  std::vector<std::vector<GlobalIndex>> connectivity;
  for (const auto& block : slice.blocks) {
    if (!named(names, block.name)) continue;
    // every rank's cells of the block: in rank order the reads ascend
    auto whole = all_gather(comm, block.connectivity);
    nodes.insert(nodes.end(), whole.begin(), whole.end());
    connectivity.push_back(std::move(whole));
    ElementBlock b;
    b.name = block.name;
    b.id = block.id;
    b.type = block.type;
    rigid.blocks.push_back(std::move(b));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  for (std::size_t b = 0; b < connectivity.size(); ++b)
    for (auto g : connectivity[b])
      rigid.blocks[b].connectivity.push_back(
          static_cast<LocalIndex>(std::lower_bound(nodes.begin(), nodes.end(), g) - nodes.begin()));
  const auto dim = static_cast<std::size_t>(slice.dimension);
  rigid.coordinates = fetch_from_slices(comm, slice.node_count, dim, slice.coordinates, nodes);
  return rigid;
}

// The slices without the rigid nodes and cells, renumbered and dealt again.
void remove_from_slices(const CommPtr& comm, const std::vector<std::string>& names,
                        const std::vector<GlobalIndex>& rigid, MeshSlice& slice) {
  const int p = comm->getSize(), rank = comm->getRank();
  const auto dim = static_cast<std::size_t>(slice.dimension);
  const auto is_rigid = [&](GlobalIndex g) {
    return std::binary_search(rigid.begin(), rigid.end(), g);
  };
  const auto renumbered = [&](GlobalIndex g) {
    return g - (std::lower_bound(rigid.begin(), rigid.end(), g) - rigid.begin());
  };
  const GlobalIndex node_count = slice.node_count - static_cast<GlobalIndex>(rigid.size());
  // Nodes: (new id, coordinates) to the holder of the new id.
  std::vector<std::vector<double>> node_out(static_cast<std::size_t>(p));
  for (std::size_t i = 0; i < slice.read_node_count(); ++i) {
    const auto g = slice.first_node + static_cast<GlobalIndex>(i);
    if (is_rigid(g)) continue;
    auto& out = node_out[static_cast<std::size_t>(slice_holder(node_count, p, renumbered(g)))];
    out.insert(out.end(), slice.coordinates.begin() + static_cast<std::ptrdiff_t>(i * dim),
               slice.coordinates.begin() + static_cast<std::ptrdiff_t>((i + 1) * dim));
  }
  slice.coordinates.clear();
  for (const auto& list : all_to_all(comm, std::move(node_out)))  // ascending: holders in order
    slice.coordinates.insert(slice.coordinates.end(), list.begin(), list.end());
  slice.node_count = node_count;
  slice.first_node = slice_begin(node_count, rank, p);
  // Cells: the kept blocks' new first cells; each cell (new id, block, nodes, thickness) to the
  // holder of its new id.
  std::vector<BlockSlice> kept;
  std::vector<GlobalIndex> old_first;
  GlobalIndex cell_count = 0;
  for (auto& block : slice.blocks) {
    if (named(names, block.name)) continue;
    old_first.push_back(block.first_cell);
    block.first_cell = cell_count;
    cell_count += block.cell_count;
    kept.push_back(std::move(block));
  }
  std::vector<std::vector<double>> cell_out(static_cast<std::size_t>(p));
  for (std::size_t b = 0; b < kept.size(); ++b) {
    auto& block = kept[b];
    const auto per = static_cast<std::size_t>(cell_node_count(block.type));
    for (std::size_t c = 0; c < block.read_count(); ++c) {
      const auto id =
          block.first_cell + (block.first_read - old_first[b]) + static_cast<GlobalIndex>(c);
      auto& out = cell_out[static_cast<std::size_t>(slice_holder(cell_count, p, id))];
      out.push_back(static_cast<double>(id));  // exact below 2^53
      out.push_back(static_cast<double>(b));
      for (std::size_t a = 0; a < per; ++a)
        out.push_back(static_cast<double>(renumbered(block.connectivity[c * per + a])));
      out.push_back(block.has_thickness ? block.thickness[c] : 0.0);
    }
    block.connectivity.clear();
    block.thickness.clear();
  }
  const auto begin = slice_begin(cell_count, rank, p);
  for (auto& block : kept)  // an empty read starts where the rank's range meets the block
    block.first_read =
        std::min(std::max(begin, block.first_cell), block.first_cell + block.cell_count);
  std::vector<bool> started(kept.size(), false);
  for (const auto& list : all_to_all(comm, std::move(cell_out)))
    for (std::size_t e = 0; e < list.size();) {
      const auto id = static_cast<GlobalIndex>(list[e]);
      auto& block = kept[static_cast<std::size_t>(list[e + 1])];
      const auto per = static_cast<std::size_t>(cell_node_count(block.type));
      if (!started[static_cast<std::size_t>(list[e + 1])]) {
        block.first_read = id;
        started[static_cast<std::size_t>(list[e + 1])] = true;
      }
      for (std::size_t a = 0; a < per; ++a)
        block.connectivity.push_back(static_cast<GlobalIndex>(list[e + 2 + a]));
      if (block.has_thickness) block.thickness.push_back(list[e + 2 + per]);
      e += 3 + per;
    }
  slice.blocks = std::move(kept);
  slice.cell_count = cell_count;
  for (auto& set : slice.node_sets) {
    std::vector<GlobalIndex> nodes;
    for (auto g : set.nodes)
      if (!is_rigid(g)) nodes.push_back(renumbered(g));
    set.nodes = std::move(nodes);
  }
}

}  // namespace

void take_rigid_blocks_from_slices(const CommPtr& comm, Scene& scene, MeshSlice& slice) {
  const auto names = rigid_block_names(scene);
  if (names.empty()) return;
  // A block the file lacks: the root path's message (every rank has the same block list).
  for (std::size_t i = 0; i < scene.rigid_bodies.size(); ++i)
    for (const auto& name : scene.rigid_bodies[i].blocks)
      if (scene.rigid_bodies[i].shape == "mesh" &&
          std::none_of(slice.blocks.begin(), slice.blocks.end(),
                       [&](const BlockSlice& b) { return b.name == name; })) {
        std::string all;
        for (const auto& b : slice.blocks) all += (all.empty() ? "" : ", ") + b.name;
        throw rigid_blocks_error(
            scene, i, "the mesh has no element block '" + name + "'; expected one of: " + all);
      }
  // The old cell ranges of the rigid blocks (for the side sets), before the blocks change.
  std::vector<std::pair<GlobalIndex, GlobalIndex>> rigid_cells;
  for (const auto& block : slice.blocks)
    if (named(names, block.name))
      rigid_cells.emplace_back(block.first_cell, block.first_cell + block.cell_count);
  std::vector<GlobalIndex> rigid_nodes;
  auto rigid = gather_rigid_blocks(comm, slice, names, rigid_nodes);
  run_collectively(comm, [&] {
    // A node of a rigid block also in a part's block would be both (the root path's check,
    // reported at the first mesh body).
    for (const auto& block : slice.blocks) {
      if (named(names, block.name)) continue;
      const auto shared =
          std::find_if(block.connectivity.begin(), block.connectivity.end(), [&](GlobalIndex g) {
            return std::binary_search(rigid_nodes.begin(), rigid_nodes.end(), g);
          });
      if (shared == block.connectivity.end()) continue;
      const auto body = std::find_if(scene.rigid_bodies.begin(), scene.rigid_bodies.end(),
                                     [](const auto& b) { return b.shape == "mesh"; });
      throw rigid_blocks_error(
          scene, static_cast<std::size_t>(body - scene.rigid_bodies.begin()),
          "the rigid blocks share node " + std::to_string(*shared + 1) +
              " with the parts' blocks; expected a body with nodes of its own");
    }
    validate_mesh(rigid, names);
    extract_rigid_blocks(scene, rigid);  // the bodies' surfaces, from the whole blocks
  });
  // Side set entries on rigid cells go, the rest shift by the rigid cells before them.
  auto new_cell = [&](GlobalIndex c) -> GlobalIndex {
    GlobalIndex before = 0;
    for (const auto& [first, end] : rigid_cells) {
      if (c >= first && c < end) return -1;
      if (end <= c) before += end - first;
    }
    return c - before;
  };
  for (auto& set : slice.side_sets) {
    std::vector<GlobalIndex> cells;
    std::vector<int> sides;
    for (std::size_t k = 0; k < set.cells.size(); ++k) {
      const auto c = new_cell(set.cells[k]);
      if (c < 0) continue;
      cells.push_back(c);
      sides.push_back(set.sides[k]);
    }
    set.cells = std::move(cells);
    set.sides = std::move(sides);
  }
  remove_from_slices(comm, names, rigid_nodes, slice);
}

}  // namespace efg
