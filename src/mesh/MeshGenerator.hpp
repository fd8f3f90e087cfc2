// Built-in structured meshes: rectangles (quad4, tri3) and boxes (hex8, tet4, wedge6), with an
// optional seeded perturbation of the nodes for meshfree robustness tests.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct GeneratorSpec {
  int dimension = 3;
  CellType element = CellType::hex8;
  std::array<double, 3> lower = {0, 0, 0};
  std::array<double, 3> upper = {1, 1, 1};
  std::array<int, 3> cells = {1, 1, 1};
  /// Largest random node displacement, as a fraction of the local spacing per direction. Nodes on
  /// a boundary plane move only within that plane, so the domain keeps its shape.
  double perturbation = 0.0;
  std::uint64_t seed = 1;
  std::string block_name = "block_1";
  /// Optional coordinate map of every node (box coordinates in, 3 entries each; mapped out), set
  /// from the scene's mesh.generate.map expressions; `map_text` describes it.
  std::function<void(const double* box, double* mapped)> coordinate_map;
  std::string map_text;
};

/// Builds the mesh. Node sets and side sets are named xmin, xmax, ymin, ymax (zmin, zmax in 3D);
/// node set "all" holds every node. Throws InputError on an invalid spec.
/// Most nodes a generated mesh may have: 3 dofs per node stay within 32-bit dof indices.
constexpr double kMaxGeneratedNodes = 2e8;

BackgroundMesh generate_mesh(const GeneratorSpec& spec);

/// Generates `spec` and appends it to `mesh` as a separate body: its own nodes (not joined to
/// the mesh's), its block, and its sets named <block_name>_xmin .. and <block_name>_all; the
/// node set "all" grows to hold every node. Throws InputError when the dimensions differ or
/// the block name is taken.
void append_generated(BackgroundMesh& mesh, const GeneratorSpec& spec);

/// A one-line description ("box 10x4x4 hex8 on [0,10]x[0,1]x[0,1], perturbation 0.2 seed 7").
std::string describe(const GeneratorSpec& spec);

}  // namespace efg
