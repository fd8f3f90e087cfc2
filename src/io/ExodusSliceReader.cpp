#include "io/ExodusSliceReader.hpp"

#include <exodusII.h>

#include <algorithm>

#include "core/Errors.hpp"
#include "io/ExodusEntities.hpp"
#include "io/ExodusFile.hpp"

namespace efg {
namespace {

// The part of [begin, end) (global) that falls in [first, first + count).
struct Overlap {
  GlobalIndex begin = 0, count = 0;
};
Overlap overlap(GlobalIndex begin, GlobalIndex end, GlobalIndex first, GlobalIndex count) {
  const auto b = std::max(begin, first), e = std::min(end, first + count);
  return e > b ? Overlap{b, e - b} : Overlap{b, 0};
}

void read_block_slices(const exodus::File& f, const std::string& path, std::int64_t nblocks,
                       int rank, int size, MeshSlice& slice) {
  const auto ids = exodus::read_ids(f, EX_ELEM_BLOCK, nblocks);
  const auto names = exodus::read_names(f, EX_ELEM_BLOCK, ids.size(), ids, "block_");
  const auto begin = slice_begin(slice.cell_count, rank, size);
  const auto end = slice_begin(slice.cell_count, rank + 1, size);
  GlobalIndex first = 0;
  for (std::size_t b = 0; b < ids.size(); ++b) {
    const auto header = exodus::read_block_header(f, path, ids[b], names[b]);
    BlockSlice block;
    block.name = names[b];
    block.id = ids[b];
    block.type = header.type;
    block.first_cell = first;
    block.cell_count = header.cells;
    block.has_thickness = header.thickness_attribute > 0;
    const auto mine = overlap(begin, end, first, header.cells);
    block.first_read = mine.begin;
    if (mine.count > 0) {
      std::vector<std::int64_t> conn(static_cast<std::size_t>(mine.count * header.per_cell));
      f.check(ex_get_partial_conn(f.id(), EX_ELEM_BLOCK, ids[b], mine.begin - first + 1, mine.count,
                                  conn.data(), nullptr, nullptr),
              "reading connectivity");
      block.connectivity.reserve(conn.size());
      for (std::size_t k = 0; k < conn.size(); ++k) {
        // checked here: the slices are routed by these indices (validate_mesh sees the parts)
        if (conn[k] < 1 || conn[k] > slice.node_count)
          throw InputError("mesh file '" + path + "': block '" + block.name + "' cell " +
                           std::to_string(mine.begin - first + 1 +
                                          static_cast<GlobalIndex>(k) / header.per_cell) +
                           " refers to node " + std::to_string(conn[k]) + ", outside 1.." +
                           std::to_string(slice.node_count));
        block.connectivity.push_back(conn[k] - 1);
      }
      if (block.has_thickness)
        block.thickness =
            exodus::read_thickness(f, path, block.name, block.id, header.thickness_attribute,
                                   mine.begin - first, mine.count);
    }
    first += header.cells;
    slice.blocks.push_back(std::move(block));
  }
  if (first != slice.cell_count)
    throw InputError("mesh file '" + path + "': header says " + std::to_string(slice.cell_count) +
                     " elements but the blocks hold " + std::to_string(first));
}

std::int64_t set_size(const exodus::File& f, ex_entity_type type, std::int64_t id) {
  std::int64_t count = 0, factors = 0;
  f.check(ex_get_set_param(f.id(), type, id, &count, &factors), "reading a set");
  return count;
}

void read_set_slices(const exodus::File& f, std::int64_t nnode_sets, std::int64_t nside_sets,
                     int rank, int size, MeshSlice& slice) {
  const auto ns_ids = exodus::read_ids(f, EX_NODE_SET, nnode_sets);
  const auto ns_names = exodus::read_names(f, EX_NODE_SET, ns_ids.size(), ns_ids, "nodeset_");
  for (std::size_t s = 0; s < ns_ids.size(); ++s) {
    const auto count = set_size(f, EX_NODE_SET, ns_ids[s]);
    const auto begin = slice_begin(count, rank, size), end = slice_begin(count, rank + 1, size);
    NodeSetSlice set{ns_names[s], ns_ids[s], begin, {}};
    std::vector<std::int64_t> entries(static_cast<std::size_t>(end - begin));
    if (!entries.empty())
      f.check(ex_get_partial_node_set(f.id(), ns_ids[s], begin + 1, end - begin, entries.data()),
              "reading a node set");
    for (auto n : entries) {
      if (n < 1 || n > slice.node_count)
        throw InputError("mesh file '" + slice.source + "': node set '" + set.name +
                         "' refers to node " + std::to_string(n) + ", outside 1.." +
                         std::to_string(slice.node_count));
      set.nodes.push_back(n - 1);
    }
    slice.node_sets.push_back(std::move(set));
  }
  const auto ss_ids = exodus::read_ids(f, EX_SIDE_SET, nside_sets);
  const auto ss_names = exodus::read_names(f, EX_SIDE_SET, ss_ids.size(), ss_ids, "sideset_");
  for (std::size_t s = 0; s < ss_ids.size(); ++s) {
    const auto count = set_size(f, EX_SIDE_SET, ss_ids[s]);
    const auto begin = slice_begin(count, rank, size), end = slice_begin(count, rank + 1, size);
    SideSetSlice set{ss_names[s], ss_ids[s], begin, {}, {}};
    std::vector<std::int64_t> cells(static_cast<std::size_t>(end - begin)), sides(cells.size());
    if (!cells.empty())
      f.check(ex_get_partial_side_set(f.id(), ss_ids[s], begin + 1, end - begin, cells.data(),
                                      sides.data()),
              "reading a side set");
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (cells[i] < 1 || cells[i] > slice.cell_count)
        throw InputError("mesh file '" + slice.source + "': side set '" + set.name +
                         "' refers to cell " + std::to_string(cells[i]) + ", outside 1.." +
                         std::to_string(slice.cell_count));
      set.cells.push_back(cells[i] - 1);
      set.sides.push_back(static_cast<int>(sides[i] - 1));
    }
    slice.side_sets.push_back(std::move(set));
  }
}

}  // namespace

MeshSlice read_exodus_slice(const std::string& path, int rank, int size) {
  auto f = exodus::File::open_read(path);
  const auto header = exodus::read_mesh_header(f, path);
  MeshSlice slice;
  slice.source = path;
  slice.dimension = header.dimension;
  slice.node_count = header.nodes;
  slice.cell_count = header.cells;
  slice.first_node = slice_begin(header.nodes, rank, size);
  slice.coordinates =
      exodus::read_coordinates(f, header.dimension, slice.first_node,
                               slice_begin(header.nodes, rank + 1, size) - slice.first_node);
  read_block_slices(f, path, header.blocks, rank, size, slice);
  read_set_slices(f, header.node_sets, header.side_sets, rank, size, slice);
  return slice;
}

}  // namespace efg
