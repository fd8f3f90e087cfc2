#include "mesh/MeshValidation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"

namespace efg {
namespace {

[[noreturn]] void fail(const BackgroundMesh& mesh, const std::string& what) {
  throw InputError("mesh '" + mesh.source + "': " + what);
}

double bounding_box_measure(int dim, const std::vector<double>& x) {
  double measure = 1.0;
  for (int d = 0; d < dim; ++d) {
    double lo = x[static_cast<std::size_t>(d)], hi = lo;
    for (std::size_t i = static_cast<std::size_t>(d); i < x.size();
         i += static_cast<std::size_t>(dim)) {
      lo = std::min(lo, x[i]);
      hi = std::max(hi, x[i]);
    }
    measure *= hi - lo;
  }
  return measure;
}

template <class Named>
void require_unique_names(const BackgroundMesh& mesh, const std::vector<Named>& items,
                          const char* what) {
  for (std::size_t i = 0; i < items.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (items[i].name == items[j].name)
        fail(mesh, "has two " + std::string(what) + " named '" + items[i].name +
                       "'; expected unique names (the scene refers to them by name)");
}

}  // namespace

void validate_mesh(const BackgroundMesh& mesh, const std::vector<std::string>& tool_blocks) {
  const auto nodes = mesh.node_count();
  if (mesh.dimension != 2 && mesh.dimension != 3)
    fail(mesh,
         "dimension " + std::to_string(mesh.dimension) + " is not supported (expected 2 or 3)");
  if (nodes == 0) fail(mesh, "has no nodes");
  if (mesh.blocks.empty()) fail(mesh, "has no element blocks");
  for (double x : mesh.coordinates)
    if (!std::isfinite(x)) fail(mesh, "has a non-finite nodal coordinate");

  // Scenes refer to blocks and sets by name: two of one kind with the same name are ambiguous.
  require_unique_names(mesh, mesh.blocks, "element blocks");
  require_unique_names(mesh, mesh.node_sets, "node sets");
  require_unique_names(mesh, mesh.side_sets, "side sets");

  std::size_t first = 0;  // this mesh's index of the block's first cell
  for (const auto& block : mesh.blocks) {
    const bool tool =
        std::find(tool_blocks.begin(), tool_blocks.end(), block.name) != tool_blocks.end();
    if (cell_dimension(block.type) != mesh.dimension &&
        !(tool && cell_dimension(block.type) == mesh.dimension - 1))
      fail(mesh, "block '" + block.name + "' holds " + cell_scene_name(block.type) +
                     " cells in a " + std::to_string(mesh.dimension) + "D mesh" +
                     (mesh.dimension == 3 ? " (surface cells in 3D are a shell surface: make the "
                                            "parts shells, parts[].shell)"
                                          : ""));
    const auto npc = static_cast<std::size_t>(cell_node_count(block.type));
    if (block.connectivity.size() % npc != 0)
      fail(mesh, "block '" + block.name + "' has a truncated connectivity array");
    std::vector<double> x(npc * static_cast<std::size_t>(mesh.dimension));
    for (std::size_t c = 0; c < block.cell_count(); ++c) {
      for (std::size_t a = 0; a < npc; ++a) {
        const auto node = block.connectivity[c * npc + a];
        if (node < 0 || static_cast<std::size_t>(node) >= nodes) {
          std::ostringstream o;
          o << "block '" << block.name << "' cell " << c + 1 << " refers to node " << node + 1
            << ", outside 1.." << nodes;
          fail(mesh, o.str());
        }
        for (int d = 0; d < mesh.dimension; ++d)
          x[a * static_cast<std::size_t>(mesh.dimension) + static_cast<std::size_t>(d)] =
              mesh.coordinates[static_cast<std::size_t>(node) *
                                   static_cast<std::size_t>(mesh.dimension) +
                               static_cast<std::size_t>(d)];
      }
      if (tool) continue;  // a rigid body's cells: indices only (its surface, not its volume)
      const auto g = cell_geometry(block.type, x.data());
      const double scale = std::abs(bounding_box_measure(mesh.dimension, x));
      if (!(g.min_corner_det > 0) || !(g.volume > degenerate_cell_tolerance * scale) ||
          scale == 0) {
        std::ostringstream o;
        o << "block '" << block.name << "' cell ";
        if (mesh.is_part())  // a rank's part: the cell by its index in the whole mesh
          o << "(mesh cell " << mesh.global_cell(first + c) + 1 << ")";
        else
          o << c + 1;
        o << " is " << (g.volume < 0 || g.min_corner_det < 0 ? "inverted" : "degenerate")
          << " (volume " << g.volume << ", smallest corner Jacobian " << g.min_corner_det
          << "); expected a positive volume with the Exodus node ordering";
        fail(mesh, o.str());
      }
    }
    first += block.cell_count();
  }
  // A node in no cell is a particle with no volume and no support of its own: the implicit
  // stiffness is singular at it, reported by the factorization without the node (issue 55). A
  // rank's part of a mesh read in slices holds halo nodes of other ranks' cells: checked whole.
  if (!mesh.is_part()) {
    std::vector<char> used(nodes, 0);
    for (const auto& block : mesh.blocks)
      for (auto node : block.connectivity) used[static_cast<std::size_t>(node)] = 1;
    const auto orphans = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
    if (orphans > 0) {
      const auto n =
          static_cast<std::size_t>(std::find(used.begin(), used.end(), 0) - used.begin());
      const auto dim = static_cast<std::size_t>(mesh.dimension);
      std::ostringstream o;
      o << "has " << orphans << " node(s) in no cell (the first: node " << n + 1 << " at (";
      for (std::size_t d = 0; d < dim; ++d) o << (d ? ", " : "") << mesh.coordinates[n * dim + d];
      o << ")); expected every node in a cell of some block (remove the unused nodes)";
      fail(mesh, o.str());
    }
  }

  for (const auto& set : mesh.node_sets)
    for (auto node : set.nodes)
      if (node < 0 || static_cast<std::size_t>(node) >= nodes)
        fail(mesh, "node set '" + set.name + "' refers to node " + std::to_string(node + 1) +
                       ", outside 1.." + std::to_string(nodes));

  const auto cells = mesh.cell_count();
  for (const auto& set : mesh.side_sets) {
    if (set.cells.size() != set.sides.size())
      fail(mesh, "side set '" + set.name + "' has different numbers of cells and sides");
    for (std::size_t i = 0; i < set.cells.size(); ++i) {
      const auto cell = set.cells[i];
      if (cell < 0 || static_cast<std::size_t>(cell) >= cells)
        fail(mesh, "side set '" + set.name + "' refers to cell " + std::to_string(cell + 1) +
                       ", outside 1.." + std::to_string(cells));
      const auto type = mesh.locate_cell(static_cast<std::size_t>(cell)).first->type;
      if (set.sides[i] < 0 || set.sides[i] >= cell_side_count(type))
        fail(mesh, "side set '" + set.name + "' names side " + std::to_string(set.sides[i] + 1) +
                       " of a " + cell_scene_name(type) + " cell, which has " +
                       std::to_string(cell_side_count(type)) + " sides");
    }
  }
}

}  // namespace efg
