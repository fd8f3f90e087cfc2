#include "mesh/GeneratorLattice.hpp"

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

// The cells of one lattice cube with corners v (bits 0:(000) 1:(100) 2:(110) 3:(010) 4:(001)
// 5:(101) 6:(111) 7:(011)); `x(a)` gives node a's box coordinates.
template <class Index, class Coordinates>
void add_cells_of_hex(const std::array<Index, 8>& v, CellType type, const Coordinates& x,
                      std::vector<Index>& conn) {
  auto push_oriented = [&](std::array<Index, 4> cell) {
    double xs[12];
    for (std::size_t a = 0; a < 4; ++a)
      for (std::size_t c = 0; c < 3; ++c) xs[3 * a + c] = x(cell[a])[c];
    if (cell_geometry(type, xs).volume < 0) std::swap(cell[1], cell[2]);
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
      const int paths[6][4] = {{0, 1, 2, 6}, {0, 1, 5, 6}, {0, 3, 2, 6},
                               {0, 3, 7, 6}, {0, 4, 5, 6}, {0, 4, 7, 6}};
      for (const auto& p : paths) push_oriented({v[p[0]], v[p[1]], v[p[2]], v[p[3]]});
      break;
    }
    default:
      break;
  }
}

// Lattice cell L's (i, j, k).
std::array<int, 3> lattice_cell_ijk(const Lattice& lat, std::size_t L) {
  const auto cx = static_cast<std::size_t>(lat.n[0] - 1),
             cy = static_cast<std::size_t>(lat.n[1] - 1);
  return {static_cast<int>(L % cx), static_cast<int>(L / cx % cy), static_cast<int>(L / cx / cy)};
}

}  // namespace

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
  }
  // A mesh this generator cannot hold is bad input, not a bad_alloc: efg indexes particles with
  // 32-bit ints, and each particle of an EFG model needs a few kilobytes. Counted in double
  // before any int holds cells + 1 (2147483647 cells overflowed to a negative count).
  double count = 1;
  for (int d = 0; d < dim; ++d)
    count *= static_cast<double>(s.cells[static_cast<std::size_t>(d)]) + 1;
  if (count <= kMaxGeneratedNodes)
    for (int d = 0; d < dim; ++d)
      lat.n[static_cast<std::size_t>(d)] = s.cells[static_cast<std::size_t>(d)] + 1;
  if (count > kMaxGeneratedNodes) {
    std::ostringstream o;
    o << "mesh generator: " << describe(s) << " has " << count << " nodes; at most "
      << kMaxGeneratedNodes << " are supported (lower cells)";
    throw InputError(o.str());
  }
  return lat;
}

int cells_per_lattice_cell(CellType type) {
  switch (type) {
    case CellType::tet4:
      return 6;
    case CellType::wedge6:
    case CellType::tri3:
      return 2;
    default:
      return 1;
  }
}

std::vector<double> lattice_box_coordinates(const GeneratorSpec& s, const Lattice& lat,
                                            std::size_t first, std::size_t count) {
  std::vector<double> xyz(3 * count, 0.0);
  std::mt19937_64 rng(s.seed);
  // One draw per node and direction, drawn for every node (boundary ones too): a stable stream.
  if (s.perturbation > 0) rng.discard(static_cast<unsigned long long>(s.dimension) * first);
  for (std::size_t g = first; g < first + count; ++g)
    for (int d = 0; d < s.dimension; ++d) {
      const auto du = static_cast<std::size_t>(d);
      const int i = lat.coordinate(g, d);
      const double h = (s.upper[du] - s.lower[du]) / s.cells[du];
      double x = s.lower[du] + h * i;
      if (s.perturbation > 0) {
        const double r = symmetric_unit(rng);
        const bool on_boundary = i == 0 || i == s.cells[du];
        if (!on_boundary) x += s.perturbation * h * r;
      }
      xyz[3 * (g - first) + du] = x;
    }
  return xyz;
}

std::array<std::size_t, 2> lattice_node_range(const GeneratorSpec& s, const Lattice& lat,
                                              std::size_t first, std::size_t end) {
  if (end <= first) return {0, 0};
  const auto m = static_cast<std::size_t>(cells_per_lattice_cell(s.element));
  const auto lo = lattice_cell_ijk(lat, first / m), hi = lattice_cell_ijk(lat, (end - 1) / m);
  return {lat.index(lo[0], lo[1], lo[2]),
          lat.index(hi[0] + 1, hi[1] + 1, hi[2] + (lat.dim == 3 ? 1 : 0)) + 1};
}

template <class Index>
void append_lattice_cells(const GeneratorSpec& s, const Lattice& lat, std::size_t first,
                          std::size_t end, const std::vector<double>& box, std::size_t box_first,
                          std::vector<Index>& conn) {
  if (end <= first) return;
  const auto m = static_cast<std::size_t>(cells_per_lattice_cell(s.element));
  const auto per = static_cast<std::size_t>(cell_node_count(s.element));
  auto x = [&](Index a) { return &box[3 * (static_cast<std::size_t>(a) - box_first)]; };
  std::vector<Index> cut;
  for (std::size_t L = first / m; L <= (end - 1) / m; ++L) {
    const auto [i, j, k] = lattice_cell_ijk(lat, L);
    auto at = [&, i = i, j = j, k = k](int di, int dj, int dk) {
      return static_cast<Index>(lat.index(i + di, j + dj, k + dk));
    };
    cut.clear();
    if (s.dimension == 2) {
      const Index q[4] = {at(0, 0, 0), at(1, 0, 0), at(1, 1, 0), at(0, 1, 0)};
      if (s.element == CellType::quad4) {
        cut.insert(cut.end(), q, q + 4);
      } else {
        cut.insert(cut.end(), {q[0], q[1], q[2]});
        cut.insert(cut.end(), {q[0], q[2], q[3]});
      }
    } else {
      const std::array<Index, 8> v = {at(0, 0, 0), at(1, 0, 0), at(1, 1, 0), at(0, 1, 0),
                                      at(0, 0, 1), at(1, 0, 1), at(1, 1, 1), at(0, 1, 1)};
      add_cells_of_hex(v, s.element, x, cut);
    }
    for (std::size_t c = 0; c < m; ++c) {
      const auto cell = L * m + c;
      if (cell < first || cell >= end) continue;
      conn.insert(conn.end(), cut.begin() + static_cast<std::ptrdiff_t>(c * per),
                  cut.begin() + static_cast<std::ptrdiff_t>((c + 1) * per));
    }
  }
}

template void append_lattice_cells<LocalIndex>(const GeneratorSpec&, const Lattice&, std::size_t,
                                               std::size_t, const std::vector<double>&, std::size_t,
                                               std::vector<LocalIndex>&);
template void append_lattice_cells<GlobalIndex>(const GeneratorSpec&, const Lattice&, std::size_t,
                                                std::size_t, const std::vector<double>&,
                                                std::size_t, std::vector<GlobalIndex>&);

std::vector<double> mesh_coordinates(const GeneratorSpec& s, std::vector<double> box) {
  const std::size_t nodes = box.size() / 3;
  if (s.coordinate_map)  // after the cells are cut: their topology is the box's
    for (std::size_t n = 0; n < nodes; ++n) {
      const double b[3] = {box[3 * n], box[3 * n + 1], box[3 * n + 2]};
      s.coordinate_map(b, &box[3 * n]);
    }
  if (s.dimension == 3) return box;
  const auto dim = static_cast<std::size_t>(s.dimension);
  std::vector<double> x(dim * nodes);
  for (std::size_t n = 0; n < nodes; ++n)
    for (std::size_t d = 0; d < dim; ++d) x[dim * n + d] = box[3 * n + d];
  return x;
}

template <class Index>
bool side_on_plane(const Lattice& lat, CellType type, const Index* cell, int side, int d,
                   int plane) {
  for (int a : cell_side_nodes(type, side))
    if (lat.coordinate(static_cast<std::size_t>(cell[a]), d) != plane) return false;
  return true;
}

template bool side_on_plane<LocalIndex>(const Lattice&, CellType, const LocalIndex*, int, int, int);
template bool side_on_plane<GlobalIndex>(const Lattice&, CellType, const GlobalIndex*, int, int,
                                         int);

std::vector<BoundaryPlane> boundary_planes(const GeneratorSpec& s) {
  std::vector<BoundaryPlane> planes;
  const char* axis = "xyz";
  for (int d = 0; d < s.dimension; ++d)
    for (int hi = 0; hi < 2; ++hi)
      planes.push_back({std::string(1, axis[d]) + (hi ? "max" : "min"), d,
                        hi ? s.cells[static_cast<std::size_t>(d)] : 0});
  return planes;
}

}  // namespace efg
