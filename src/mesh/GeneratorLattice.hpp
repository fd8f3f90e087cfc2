// The node lattice behind the built-in meshes (mesh/MeshGenerator.hpp), in pieces: the
// coordinates of any range of nodes and the cells of any range of cells, each equal to that
// range of the whole generated mesh. The whole mesh is one range; a distributed generation
// (mesh/GeneratedSlice.hpp) takes each rank's range, so no rank ever makes the whole mesh.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "mesh/MeshGenerator.hpp"

namespace efg {

struct Lattice {
  int dim = 3;
  std::array<int, 3> n = {1, 1, 1};  ///< nodes per direction (1 in z for 2D)

  std::size_t node_count() const {
    return static_cast<std::size_t>(n[0]) * static_cast<std::size_t>(n[1]) *
           static_cast<std::size_t>(n[2]);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(n[0]) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(k));
  }
  /// The lattice coordinate of `node` along d: which plane x_d = lower_d + h_d i it lies on.
  int coordinate(std::size_t node, int d) const {
    std::size_t stride = 1;
    for (int e = 0; e < d; ++e) stride *= static_cast<std::size_t>(n[static_cast<std::size_t>(e)]);
    return static_cast<int>(node / stride %
                            static_cast<std::size_t>(n[static_cast<std::size_t>(d)]));
  }
  /// Lattice cells (squares or cubes), each cut into cells_per_lattice_cell cells.
  std::size_t lattice_cell_count() const {
    return static_cast<std::size_t>(n[0] - 1) * static_cast<std::size_t>(n[1] - 1) *
           static_cast<std::size_t>(dim == 3 ? n[2] - 1 : 1);
  }
};

/// The spec's lattice, after checking that the spec makes a mesh this code can hold; throws
/// InputError otherwise.
Lattice checked_lattice(const GeneratorSpec& spec);

/// Cells cut from each lattice cell: 1 (hex8, quad4), 2 (wedge6, tri3), 6 (tet4).
int cells_per_lattice_cell(CellType type);

/// Cells of the whole generated mesh.
inline std::size_t generated_cell_count(const GeneratorSpec& spec, const Lattice& lat) {
  return lat.lattice_cell_count() * static_cast<std::size_t>(cells_per_lattice_cell(spec.element));
}

/// Box coordinates (before the coordinate map; 3 per node, z = 0 in 2D) of the nodes
/// [first, first + count). Node g's perturbation takes draws dimension x g .. of the seeded
/// stream, so any range gives the whole mesh's values.
std::vector<double> lattice_box_coordinates(const GeneratorSpec& spec, const Lattice& lat,
                                            std::size_t first, std::size_t count);

/// The nodes the cells [first, end) use: [first node, one past the last).
std::array<std::size_t, 2> lattice_node_range(const GeneratorSpec& spec, const Lattice& lat,
                                              std::size_t first, std::size_t end);

/// Appends the connectivity (lattice node indices) of cells [first, end) in the whole mesh's
/// order. `box` holds the box coordinates of nodes from `box_first` on, at least
/// lattice_node_range's (tetrahedra are oriented by them).
template <class Index>
void append_lattice_cells(const GeneratorSpec& spec, const Lattice& lat, std::size_t first,
                          std::size_t end, const std::vector<double>& box, std::size_t box_first,
                          std::vector<Index>& connectivity);

/// The mesh coordinates (`dimension` per node) of box coordinates (3 per node): mapped by the
/// spec's coordinate map, if any.
std::vector<double> mesh_coordinates(const GeneratorSpec& spec, std::vector<double> box);

/// Whether side `side` of a cell with lattice nodes `cell` lies on the plane of lattice
/// coordinate `plane` along d (exact despite perturbation).
template <class Index>
bool side_on_plane(const Lattice& lat, CellType type, const Index* cell, int side, int d,
                   int plane);

/// The boundary planes' set names in the generator's order: xmin, xmax, ymin, ... and their
/// (axis, lattice coordinate).
struct BoundaryPlane {
  std::string name;
  int axis = 0;
  int coordinate = 0;
};
std::vector<BoundaryPlane> boundary_planes(const GeneratorSpec& spec);

}  // namespace efg
