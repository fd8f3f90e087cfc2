#include "mesh/MeshGenerator.hpp"

#include <algorithm>
#include <sstream>

#include "core/Errors.hpp"
#include "mesh/GeneratorLattice.hpp"

namespace efg {

std::string describe(const GeneratorSpec& s) {
  std::ostringstream o;
  o << (s.dimension == 2 ? "rectangle " : "box ") << s.cells[0] << "x" << s.cells[1];
  if (s.dimension == 3) o << "x" << s.cells[2];
  o << " " << cell_scene_name(s.element) << " on ";
  for (int d = 0; d < s.dimension; ++d)
    o << (d ? "x" : "") << "[" << s.lower[static_cast<std::size_t>(d)] << ","
      << s.upper[static_cast<std::size_t>(d)] << "]";
  if (s.perturbation > 0) o << ", perturbation " << s.perturbation << " seed " << s.seed;
  if (s.coordinate_map) o << ", mapped to " << s.map_text;
  return o.str();
}

namespace {

// Boundary sets xmin..zmax (nodes and sides) and "all": a node is on a plane by its lattice
// coordinate, exact despite perturbation.
void add_boundary_sets(const GeneratorSpec& s, const Lattice& lat, BackgroundMesh& mesh) {
  const std::size_t nodes = mesh.node_count();
  const auto& b = mesh.blocks.front();
  const auto per = static_cast<std::size_t>(cell_node_count(b.type));
  std::int64_t set_id = 1;
  for (const auto& plane : boundary_planes(s)) {
    NodeSet ns{plane.name, set_id, {}};
    for (std::size_t n = 0; n < nodes; ++n)
      if (lat.coordinate(n, plane.axis) == plane.coordinate)
        ns.nodes.push_back(static_cast<LocalIndex>(n));
    SideSet ss{plane.name, set_id, {}, {}};
    for (std::size_t c = 0; c < b.cell_count(); ++c)
      for (int side = 0; side < cell_side_count(b.type); ++side)
        if (side_on_plane(lat, b.type, &b.connectivity[c * per], side, plane.axis,
                          plane.coordinate)) {
          ss.cells.push_back(static_cast<LocalIndex>(c));
          ss.sides.push_back(side);
        }
    mesh.node_sets.push_back(std::move(ns));
    mesh.side_sets.push_back(std::move(ss));
    ++set_id;
  }
  NodeSet all{"all", set_id, {}};
  for (std::size_t n = 0; n < nodes; ++n) all.nodes.push_back(static_cast<LocalIndex>(n));
  mesh.node_sets.push_back(std::move(all));
}

}  // namespace

BackgroundMesh generate_mesh(const GeneratorSpec& s) {
  const Lattice lat = checked_lattice(s);
  BackgroundMesh mesh;
  mesh.dimension = s.dimension;
  mesh.source = "generated " + describe(s);
  const std::size_t nodes = lat.node_count();
  auto box = lattice_box_coordinates(s, lat, 0, nodes);
  ElementBlock block;
  block.name = s.block_name;
  block.id = 1;
  block.type = s.element;
  append_lattice_cells(s, lat, 0, generated_cell_count(s, lat), box, 0, block.connectivity);
  mesh.blocks.push_back(std::move(block));
  mesh.coordinates = mesh_coordinates(s, std::move(box));
  add_boundary_sets(s, lat, mesh);
  return mesh;
}

void append_generated(BackgroundMesh& mesh, const GeneratorSpec& spec) {
  if (spec.dimension != mesh.dimension)
    throw InputError("a " + std::to_string(spec.dimension) + "D block cannot join a " +
                     std::to_string(mesh.dimension) + "D mesh (expected " +
                     std::to_string(mesh.dimension) + "D cells)");
  if (mesh.find_block(spec.block_name))
    throw InputError("block name '" + spec.block_name +
                     "' is taken (expected a block_name of its own)");
  const auto body = generate_mesh(spec);
  const auto offset = static_cast<LocalIndex>(mesh.node_count());
  const auto cell_offset = static_cast<LocalIndex>(mesh.cell_count());
  std::int64_t block_id = 0, set_id = 0;
  for (const auto& b : mesh.blocks) block_id = std::max(block_id, b.id);
  for (const auto& s : mesh.node_sets) set_id = std::max(set_id, s.id);
  for (const auto& s : mesh.side_sets) set_id = std::max(set_id, s.id);
  mesh.coordinates.insert(mesh.coordinates.end(), body.coordinates.begin(), body.coordinates.end());
  for (auto block : body.blocks) {
    for (auto& n : block.connectivity) n += offset;
    block.id = ++block_id;
    mesh.blocks.push_back(std::move(block));
  }
  const auto prefix = spec.block_name + "_";
  for (auto set : body.node_sets) {
    for (auto& n : set.nodes) n += offset;
    if (set.name == "all")
      for (auto& all : mesh.node_sets)
        if (all.name == "all")
          all.nodes.insert(all.nodes.end(), set.nodes.begin(), set.nodes.end());
    set.name = prefix + set.name;
    set.id = ++set_id;
    mesh.node_sets.push_back(std::move(set));
  }
  for (auto set : body.side_sets) {
    for (auto& c : set.cells) c += cell_offset;
    set.name = prefix + set.name;
    set.id = ++set_id;
    mesh.side_sets.push_back(std::move(set));
  }
  mesh.source += " + " + describe(spec);
}

}  // namespace efg
