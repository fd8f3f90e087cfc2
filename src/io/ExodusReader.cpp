#include "io/ExodusReader.hpp"

#include <exodusII.h>

#include <cstdint>

#include "core/Errors.hpp"
#include "io/ExodusEntities.hpp"
#include "io/ExodusFile.hpp"

namespace efg {
namespace {

constexpr int kNameLength = exodus::kNameLength;
using exodus::read_variable_names;

void read_blocks(const exodus::File& f, const std::string& path, std::int64_t nblocks,
                 BackgroundMesh& mesh) {
  const auto block_ids = exodus::read_ids(f, EX_ELEM_BLOCK, nblocks);
  const auto block_names =
      exodus::read_names(f, EX_ELEM_BLOCK, block_ids.size(), block_ids, "block_");
  for (std::size_t b = 0; b < block_ids.size(); ++b) {
    const auto header = exodus::read_block_header(f, path, block_ids[b], block_names[b]);
    ElementBlock block;
    block.name = block_names[b];
    block.id = block_ids[b];
    block.type = header.type;
    std::vector<std::int64_t> conn(static_cast<std::size_t>(header.cells * header.per_cell));
    if (!conn.empty())
      f.check(ex_get_conn(f.id(), EX_ELEM_BLOCK, block_ids[b], conn.data(), nullptr, nullptr),
              "reading connectivity");
    block.connectivity.reserve(conn.size());
    for (auto n : conn) block.connectivity.push_back(static_cast<LocalIndex>(n - 1));
    if (header.thickness_attribute > 0)
      block.thickness = exodus::read_thickness(f, path, block.name, block.id,
                                               header.thickness_attribute, 0, header.cells);
    mesh.blocks.push_back(std::move(block));
  }
}

void read_node_sets(const exodus::File& f, std::int64_t nnode_sets, BackgroundMesh& mesh) {
  const auto ns_ids = exodus::read_ids(f, EX_NODE_SET, nnode_sets);
  const auto ns_names = exodus::read_names(f, EX_NODE_SET, ns_ids.size(), ns_ids, "nodeset_");
  for (std::size_t s = 0; s < ns_ids.size(); ++s) {
    std::int64_t count = 0, factors = 0;
    f.check(ex_get_set_param(f.id(), EX_NODE_SET, ns_ids[s], &count, &factors),
            "reading a node set");
    std::vector<std::int64_t> entries(static_cast<std::size_t>(count));
    if (count > 0)
      f.check(ex_get_set(f.id(), EX_NODE_SET, ns_ids[s], entries.data(), nullptr),
              "reading a node set");
    NodeSet set{ns_names[s], ns_ids[s], {}};
    for (auto n : entries) set.nodes.push_back(static_cast<LocalIndex>(n - 1));
    mesh.node_sets.push_back(std::move(set));
  }
}

void read_side_sets(const exodus::File& f, std::int64_t nside_sets, BackgroundMesh& mesh) {
  const auto ss_ids = exodus::read_ids(f, EX_SIDE_SET, nside_sets);
  const auto ss_names = exodus::read_names(f, EX_SIDE_SET, ss_ids.size(), ss_ids, "sideset_");
  for (std::size_t s = 0; s < ss_ids.size(); ++s) {
    std::int64_t count = 0, factors = 0;
    f.check(ex_get_set_param(f.id(), EX_SIDE_SET, ss_ids[s], &count, &factors),
            "reading a side set");
    std::vector<std::int64_t> elems(static_cast<std::size_t>(count)), sides(elems.size());
    if (count > 0)
      f.check(ex_get_set(f.id(), EX_SIDE_SET, ss_ids[s], elems.data(), sides.data()),
              "reading a side set");
    SideSet set{ss_names[s], ss_ids[s], {}, {}};
    for (std::size_t i = 0; i < elems.size(); ++i) {
      set.cells.push_back(static_cast<LocalIndex>(elems[i] - 1));
      set.sides.push_back(static_cast<int>(sides[i] - 1));
    }
    mesh.side_sets.push_back(std::move(set));
  }
}

}  // namespace

BackgroundMesh read_exodus_mesh(const std::string& path) {
  auto f = exodus::File::open_read(path);
  const auto header = exodus::read_mesh_header(f, path);
  BackgroundMesh mesh;
  mesh.source = path;
  mesh.dimension = header.dimension;
  mesh.coordinates = exodus::read_coordinates(f, header.dimension, 0, header.nodes);
  read_blocks(f, path, header.blocks, mesh);
  read_node_sets(f, header.node_sets, mesh);
  read_side_sets(f, header.side_sets, mesh);
  const auto cells = header.cells;
  if (static_cast<std::int64_t>(mesh.cell_count()) != cells)
    throw InputError("mesh file '" + path + "': header says " + std::to_string(cells) +
                     " elements but the blocks hold " + std::to_string(mesh.cell_count()));
  return mesh;
}

ExodusResults read_exodus_results(const std::string& path) {
  auto f = exodus::File::open_read(path);
  ex_set_max_name_length(f.id(), kNameLength);
  ExodusResults r;
  const auto steps = static_cast<int>(ex_inquire_int(f.id(), EX_INQ_TIME));
  const auto nodes = ex_inquire_int(f.id(), EX_INQ_NODES);
  const auto nblocks = ex_inquire_int(f.id(), EX_INQ_ELEM_BLK);
  const auto block_ids = exodus::read_ids(f, EX_ELEM_BLOCK, nblocks);
  std::vector<std::int64_t> block_sizes;
  for (auto id : block_ids) block_sizes.push_back(exodus::block_cell_count(f, id));
  const auto nodal_names = read_variable_names(f, EX_NODAL);
  const auto element_names = read_variable_names(f, EX_ELEM_BLOCK);
  const auto global_names = read_variable_names(f, EX_GLOBAL);
  std::vector<double> globals(global_names.size());
  for (int step = 1; step <= steps; ++step) {
    double t = 0;
    f.check(ex_get_time(f.id(), step, &t), "reading a time value");
    r.times.push_back(t);
    for (std::size_t v = 0; v < nodal_names.size(); ++v) {
      std::vector<double> values(static_cast<std::size_t>(nodes));
      f.check(ex_get_var(f.id(), step, EX_NODAL, static_cast<int>(v + 1), 1, nodes, values.data()),
              "reading a nodal variable");
      r.nodal[nodal_names[v]].push_back(std::move(values));
    }
    for (std::size_t v = 0; v < element_names.size(); ++v) {
      std::vector<double> values;
      for (std::size_t b = 0; b < block_ids.size(); ++b) {
        std::vector<double> part(static_cast<std::size_t>(block_sizes[b]));
        f.check(ex_get_var(f.id(), step, EX_ELEM_BLOCK, static_cast<int>(v + 1), block_ids[b],
                           block_sizes[b], part.data()),
                "reading an element variable");
        values.insert(values.end(), part.begin(), part.end());
      }
      r.element[element_names[v]].push_back(std::move(values));
    }
    if (!globals.empty()) {
      f.check(ex_get_glob_vars(f.id(), step, static_cast<int>(globals.size()), globals.data()),
              "reading global variables");
      for (std::size_t v = 0; v < globals.size(); ++v)
        r.global[global_names[v]].push_back(globals[v]);
    }
  }
  return r;
}

}  // namespace efg
