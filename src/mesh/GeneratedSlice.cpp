#include "mesh/GeneratedSlice.hpp"

#include <algorithm>

#include "core/Errors.hpp"
#include "mesh/GeneratorLattice.hpp"

namespace efg {
namespace {

// How many of the indices [0, g) of a mixed-radix numbering (digit 0 fastest, radices r) have
// digit d equal to q.
std::size_t count_with_digit(const std::array<std::size_t, 3>& r, std::size_t g, int d,
                             std::size_t q) {
  std::size_t stride = 1;
  for (int e = 0; e < d; ++e) stride *= r[static_cast<std::size_t>(e)];
  const std::size_t block = stride * r[static_cast<std::size_t>(d)];
  const std::size_t rest = g % block;
  const std::size_t partial =
      rest > q * stride ? std::min(rest - q * stride, stride) : std::size_t{0};
  return g / block * stride + partial;
}

// One generated body of the whole mesh: its lattice and where its nodes and cells start.
struct Body {
  const GeneratorSpec* spec = nullptr;
  Lattice lat;
  std::size_t nodes = 0, cells = 0, node_offset = 0, cell_offset = 0;
};

// The part of [begin, end) in [first, first + count), relative to first.
struct Range {
  std::size_t begin = 0, end = 0;
  bool empty() const { return end <= begin; }
};
Range overlap(std::size_t begin, std::size_t end, std::size_t first, std::size_t count) {
  const auto b = std::max(begin, first), e = std::min(end, first + count);
  return e > b ? Range{b - first, e - first} : Range{0, 0};
}

// The cells [first, end) of a body (lattice node indices) with the box coordinates they need.
std::vector<GlobalIndex> body_cells(const Body& body, std::size_t first, std::size_t end) {
  std::vector<GlobalIndex> conn;
  const auto nodes = lattice_node_range(*body.spec, body.lat, first, end);
  const auto box = lattice_box_coordinates(*body.spec, body.lat, nodes[0], nodes[1] - nodes[0]);
  append_lattice_cells(*body.spec, body.lat, first, end, box, nodes[0], conn);
  return conn;
}

// Entries of the side set on `plane` among the cells `conn` (lattice nodes), in cell then side
// order, as (cell index within conn, side).
std::vector<std::pair<std::size_t, int>> sides_on(const Body& body, const BoundaryPlane& plane,
                                                  const std::vector<GlobalIndex>& conn) {
  const auto type = body.spec->element;
  const auto per = static_cast<std::size_t>(cell_node_count(type));
  std::vector<std::pair<std::size_t, int>> sides;
  for (std::size_t c = 0; c * per < conn.size(); ++c)
    for (int side = 0; side < cell_side_count(type); ++side)
      if (side_on_plane(body.lat, type, &conn[c * per], side, plane.axis, plane.coordinate))
        sides.emplace_back(c, side);
  return sides;
}

// The side set on `plane`'s entries in the body's cells before `cell`: every lattice cell on
// the plane holds the same number of them (the same cut), plus those of the cut lattice cell.
std::size_t sides_before(const Body& body, const BoundaryPlane& plane, std::size_t cell) {
  const auto& lat = body.lat;
  const auto m = static_cast<std::size_t>(cells_per_lattice_cell(body.spec->element));
  const std::array<std::size_t, 3> r = {static_cast<std::size_t>(lat.n[0] - 1),
                                        static_cast<std::size_t>(lat.n[1] - 1),
                                        static_cast<std::size_t>(lat.dim == 3 ? lat.n[2] - 1 : 1)};
  const auto q = static_cast<std::size_t>(
      std::min(plane.coordinate, static_cast<int>(r[static_cast<std::size_t>(plane.axis)]) - 1));
  // A lattice cell on the plane: coordinate q along the axis, 0 along the others.
  std::size_t stride = 1;
  for (int e = 0; e < plane.axis; ++e) stride *= r[static_cast<std::size_t>(e)];
  const auto on_plane = q * stride;
  const auto per_lattice_cell =
      sides_on(body, plane, body_cells(body, on_plane * m, on_plane * m + m)).size();
  std::size_t count = count_with_digit(r, cell / m, plane.axis, q) * per_lattice_cell;
  if (cell % m != 0) count += sides_on(body, plane, body_cells(body, cell / m * m, cell)).size();
  return count;
}

}  // namespace

MeshSlice generate_slice(const GeneratorSpec& main, const std::vector<GeneratorSpec>& more,
                         int rank, int size) {
  std::vector<Body> bodies;
  MeshSlice slice;
  slice.dimension = main.dimension;
  slice.source = "generated " + describe(main);
  std::size_t node_count = 0, cell_count = 0;
  for (std::size_t b = 0; b <= more.size(); ++b) {
    Body body;
    body.spec = b == 0 ? &main : &more[b - 1];
    if (b > 0) {
      if (body.spec->dimension != main.dimension)
        throw InputError("a " + std::to_string(body.spec->dimension) + "D block cannot join a " +
                         std::to_string(main.dimension) + "D mesh (expected " +
                         std::to_string(main.dimension) + "D cells)");
      for (const auto& other : bodies)
        if (other.spec->block_name == body.spec->block_name)
          throw InputError("block name '" + body.spec->block_name +
                           "' is taken (expected a block_name of its own)");
      slice.source += " + " + describe(*body.spec);
    }
    body.lat = checked_lattice(*body.spec);
    body.nodes = body.lat.node_count();
    body.cells = generated_cell_count(*body.spec, body.lat);
    body.node_offset = node_count;
    body.cell_offset = cell_count;
    node_count += body.nodes;
    cell_count += body.cells;
    bodies.push_back(body);
  }
  slice.node_count = static_cast<GlobalIndex>(node_count);
  slice.cell_count = static_cast<GlobalIndex>(cell_count);
  const auto first_node = static_cast<std::size_t>(slice_begin(slice.node_count, rank, size));
  const auto end_node = static_cast<std::size_t>(slice_begin(slice.node_count, rank + 1, size));
  const auto first_cell = static_cast<std::size_t>(slice_begin(slice.cell_count, rank, size));
  const auto end_cell = static_cast<std::size_t>(slice_begin(slice.cell_count, rank + 1, size));
  slice.first_node = static_cast<GlobalIndex>(first_node);

  std::int64_t set_id = 0;
  NodeSetSlice all;  // "all": every node of every body, in their order
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto& body = bodies[b];
    const auto& spec = *body.spec;
    const auto planes = boundary_planes(spec);
    const std::string prefix = b == 0 ? "" : spec.block_name + "_";
    const auto nodes = overlap(first_node, end_node, body.node_offset, body.nodes);
    const auto cells = overlap(first_cell, end_cell, body.cell_offset, body.cells);
    const auto offset = static_cast<GlobalIndex>(body.node_offset);
    if (!nodes.empty()) {
      const auto x = mesh_coordinates(
          spec, lattice_box_coordinates(spec, body.lat, nodes.begin, nodes.end - nodes.begin));
      slice.coordinates.insert(slice.coordinates.end(), x.begin(), x.end());
    }
    BlockSlice block;
    block.name = spec.block_name;
    block.id = static_cast<std::int64_t>(b + 1);
    block.type = spec.element;
    block.first_cell = static_cast<GlobalIndex>(body.cell_offset);
    block.cell_count = static_cast<GlobalIndex>(body.cells);
    block.first_read = static_cast<GlobalIndex>(std::max(first_cell, body.cell_offset));
    const auto conn = body_cells(body, cells.begin, cells.end);
    // Node sets of the boundary planes, then the body's "all"; ids continue append_generated's.
    const auto first_plane_id = set_id;
    for (const auto& plane : planes) {
      NodeSetSlice set;
      set.name = prefix + plane.name;
      set.id = ++set_id;
      const std::array<std::size_t, 3> r = {static_cast<std::size_t>(body.lat.n[0]),
                                            static_cast<std::size_t>(body.lat.n[1]),
                                            static_cast<std::size_t>(body.lat.n[2])};
      set.first_entry = static_cast<GlobalIndex>(
          count_with_digit(r, nodes.begin, plane.axis, static_cast<std::size_t>(plane.coordinate)));
      for (auto n = nodes.begin; n < nodes.end; ++n)
        if (body.lat.coordinate(n, plane.axis) == plane.coordinate)
          set.nodes.push_back(static_cast<GlobalIndex>(n) + offset);
      slice.node_sets.push_back(std::move(set));
    }
    // The body's "all" (the first body's is the mesh's "all": every node of every body, this
    // slice's range of them, so it is filled once every body is done).
    if (b == 0) {
      all.name = "all";
      all.id = ++set_id;
      all.first_entry = static_cast<GlobalIndex>(first_node);
      slice.node_sets.emplace_back();  // its place: after the first body's planes
    } else {
      NodeSetSlice body_all;
      body_all.name = prefix + "all";
      body_all.id = ++set_id;
      body_all.first_entry = static_cast<GlobalIndex>(nodes.begin);
      for (auto n = nodes.begin; n < nodes.end; ++n)
        body_all.nodes.push_back(static_cast<GlobalIndex>(n) + offset);
      slice.node_sets.push_back(std::move(body_all));
    }
    for (auto n = nodes.begin; n < nodes.end; ++n)
      all.nodes.push_back(static_cast<GlobalIndex>(n) + offset);
    // Side sets of the planes: a whole mesh numbers them after the node sets (append_generated)
    // or beside them (the first body: the plane's node set's id).
    for (std::size_t k = 0; k < planes.size(); ++k) {
      SideSetSlice set;
      set.name = prefix + planes[k].name;
      set.id = b == 0 ? first_plane_id + static_cast<std::int64_t>(k) + 1 : ++set_id;
      set.first_entry = static_cast<GlobalIndex>(sides_before(body, planes[k], cells.begin));
      for (const auto& [c, side] : sides_on(body, planes[k], conn)) {
        set.cells.push_back(static_cast<GlobalIndex>(body.cell_offset + cells.begin + c));
        set.sides.push_back(side);
      }
      slice.side_sets.push_back(std::move(set));
    }
    block.connectivity = conn;
    for (auto& n : block.connectivity) n += offset;
    slice.blocks.push_back(std::move(block));
  }
  slice.node_sets[boundary_planes(main).size()] = std::move(all);
  return slice;
}

}  // namespace efg
