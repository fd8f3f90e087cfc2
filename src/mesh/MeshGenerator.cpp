#include "mesh/MeshGenerator.hpp"

#include <algorithm>
#include <random>
#include <sstream>

#include "core/Errors.hpp"

namespace efg {
namespace {

// Uniform in [-1, 1] from raw 64-bit draws: the same numbers on every platform and library
// (std::uniform_real_distribution is implementation-defined).
double symmetric_unit(std::mt19937_64& rng) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return 2.0 * u - 1.0;
}

struct Lattice {
  int dim;
  std::array<int, 3> n;  // nodes per direction
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(n[0]) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(k));
  }
};

void add_cells_of_hex(const std::array<LocalIndex, 8>& v, CellType type, const double* coords,
                      std::vector<LocalIndex>& conn) {
  auto push_oriented = [&](std::vector<LocalIndex> cell) {
    std::vector<double> x;
    for (auto a : cell)
      for (int c = 0; c < 3; ++c) x.push_back(coords[3 * static_cast<std::size_t>(a) + c]);
    if (cell_geometry(type, x.data()).volume < 0) std::swap(cell[1], cell[2]);
    conn.insert(conn.end(), cell.begin(), cell.end());
  };
  switch (type) {
    case CellType::hex8:
      conn.insert(conn.end(), v.begin(), v.end());
      break;
    case CellType::wedge6:
      // Prisms along z: the bottom face (0,1,2,3) is split by its 0-2 diagonal.
      conn.insert(conn.end(), {v[0], v[1], v[2], v[4], v[5], v[6]});
      conn.insert(conn.end(), {v[0], v[2], v[3], v[4], v[6], v[7]});
      break;
    case CellType::tet4: {
      // Kuhn (Freudenthal) split into 6 tets along the 0-6 diagonal: conforming between
      // neighbouring cubes because every cube uses the same diagonal direction.
      // Vertex bits: 0:(000) 1:(100) 2:(110) 3:(010) 4:(001) 5:(101) 6:(111) 7:(011).
      const int paths[6][4] = {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 3, 2, 6},
                               {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 7, 6}};
      for (const auto& p : paths) push_oriented({v[p[0]], v[p[1]], v[p[2]], v[p[3]]});
      break;
    }
    default:
      break;
  }
}

}  // namespace

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

// The node lattice of the spec, after checking that the spec makes a mesh this code can hold.
Lattice checked_lattice(const GeneratorSpec& s) {
  const int dim = s.dimension;
  if (cell_dimension(s.element) != dim)
    throw InputError("mesh generator: element " + cell_scene_name(s.element) + " does not fit a " +
                     std::to_string(dim) + "D domain");
  Lattice lat{dim, {1, 1, 1}};
  for (int d = 0; d < dim; ++d) {
    const auto du = static_cast<std::size_t>(d);
    if (s.cells[du] < 1) throw InputError("mesh generator: cells must be >= 1 in every direction");
    if (!(s.upper[du] > s.lower[du]))
      throw InputError("mesh generator: upper must exceed lower in every direction");
    lat.n[du] = s.cells[du] + 1;
  }
  // A mesh this generator cannot hold is bad input, not a bad_alloc: efg indexes particles with
  // 32-bit ints, and each particle of an EFG model needs a few kilobytes.
  const double count = static_cast<double>(lat.n[0]) * lat.n[1] * lat.n[2];
  if (count > kMaxGeneratedNodes) {
    std::ostringstream o;
    o << "mesh generator: " << describe(s) << " has " << count << " nodes; at most "
      << kMaxGeneratedNodes << " are supported (lower cells)";
    throw InputError(o.str());
  }
  return lat;
}

// Node coordinates, 3 per node (z = 0 in 2D); interior nodes perturbed by the seeded draw.
std::vector<double> lattice_coordinates(const GeneratorSpec& s, const Lattice& lat,
                                        std::size_t nodes) {
  std::vector<double> xyz(3 * nodes, 0.0);
  std::mt19937_64 rng(s.seed);
  for (int k = 0; k < lat.n[2]; ++k)
    for (int j = 0; j < lat.n[1]; ++j)
      for (int i = 0; i < lat.n[0]; ++i) {
        const std::array<int, 3> ijk = {i, j, k};
        const std::size_t node = lat.index(i, j, k);
        for (int d = 0; d < s.dimension; ++d) {
          const auto du = static_cast<std::size_t>(d);
          const double h = (s.upper[du] - s.lower[du]) / s.cells[du];
          double x = s.lower[du] + h * ijk[du];
          if (s.perturbation > 0) {
            const double r = symmetric_unit(rng);  // drawn for every node: stable sequence
            const bool on_boundary = ijk[du] == 0 || ijk[du] == s.cells[du];
            if (!on_boundary) x += s.perturbation * h * r;
          }
          xyz[3 * node + du] = x;
        }
      }
  return xyz;
}

ElementBlock lattice_block(const GeneratorSpec& s, const Lattice& lat,
                           const std::vector<double>& xyz) {
  ElementBlock block;
  block.name = s.block_name;
  block.id = 1;
  block.type = s.element;
  const int ck = s.dimension == 3 ? s.cells[2] : 1;
  for (int k = 0; k < ck; ++k)
    for (int j = 0; j < s.cells[1]; ++j)
      for (int i = 0; i < s.cells[0]; ++i) {
        auto at = [&](int di, int dj, int dk) {
          return static_cast<LocalIndex>(lat.index(i + di, j + dj, k + dk));
        };
        if (s.dimension == 2) {
          const LocalIndex q[4] = {at(0, 0, 0), at(1, 0, 0), at(1, 1, 0), at(0, 1, 0)};
          if (s.element == CellType::quad4) {
            block.connectivity.insert(block.connectivity.end(), q, q + 4);
          } else {
            block.connectivity.insert(block.connectivity.end(), {q[0], q[1], q[2]});
            block.connectivity.insert(block.connectivity.end(), {q[0], q[2], q[3]});
          }
        } else {
          const std::array<LocalIndex, 8> v = {at(0, 0, 0), at(1, 0, 0), at(1, 1, 0), at(0, 1, 0),
                                               at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)};
          add_cells_of_hex(v, s.element, xyz.data(), block.connectivity);
        }
      }
  return block;
}

// Boundary sets xmin..zmax (nodes and sides) and "all": a node is on plane (d, lo/hi) by its
// lattice index, exact despite perturbation.
void add_boundary_sets(const GeneratorSpec& s, const Lattice& lat, BackgroundMesh& mesh) {
  const std::size_t nodes = mesh.node_count();
  const char* axis = "xyz";
  auto lattice_coord = [&](std::size_t node, int d) {
    std::size_t rest = node;
    std::array<std::size_t, 3> ijk{};
    for (int e = 0; e < 3; ++e) {
      ijk[static_cast<std::size_t>(e)] =
          rest % static_cast<std::size_t>(lat.n[static_cast<std::size_t>(e)]);
      rest /= static_cast<std::size_t>(lat.n[static_cast<std::size_t>(e)]);
    }
    return static_cast<int>(ijk[static_cast<std::size_t>(d)]);
  };
  std::int64_t set_id = 1;
  for (int d = 0; d < s.dimension; ++d)
    for (int hi = 0; hi < 2; ++hi) {
      const int plane = hi ? s.cells[static_cast<std::size_t>(d)] : 0;
      const std::string name = std::string(1, axis[d]) + (hi ? "max" : "min");
      NodeSet ns{name, set_id, {}};
      for (std::size_t n = 0; n < nodes; ++n)
        if (lattice_coord(n, d) == plane) ns.nodes.push_back(static_cast<LocalIndex>(n));
      SideSet ss{name, set_id, {}, {}};
      const auto& b = mesh.blocks.front();
      for (std::size_t c = 0; c < b.cell_count(); ++c)
        for (int side = 0; side < cell_side_count(b.type); ++side) {
          bool on_plane = true;
          for (auto node : mesh.side_node_indices(c, side))
            on_plane = on_plane && lattice_coord(static_cast<std::size_t>(node), d) == plane;
          if (on_plane) {
            ss.cells.push_back(static_cast<LocalIndex>(c));
            ss.sides.push_back(side);
          }
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
  const int dim = s.dimension;
  BackgroundMesh mesh;
  mesh.dimension = dim;
  mesh.source = "generated " + describe(s);
  const std::size_t nodes = static_cast<std::size_t>(lat.n[0]) *
                            static_cast<std::size_t>(lat.n[1]) * static_cast<std::size_t>(lat.n[2]);
  auto xyz = lattice_coordinates(s, lat, nodes);  // 3 components, trimmed for 2D below
  mesh.blocks.push_back(lattice_block(s, lat, xyz));
  if (s.coordinate_map)  // after the cells are cut: their topology is the box's
    for (std::size_t n = 0; n < nodes; ++n) {
      const double box[3] = {xyz[3 * n], xyz[3 * n + 1], xyz[3 * n + 2]};
      s.coordinate_map(box, &xyz[3 * n]);
    }
  mesh.coordinates.resize(static_cast<std::size_t>(dim) * nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    for (int d = 0; d < dim; ++d)
      mesh.coordinates[static_cast<std::size_t>(dim) * n + static_cast<std::size_t>(d)] =
          xyz[3 * n + static_cast<std::size_t>(d)];
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
