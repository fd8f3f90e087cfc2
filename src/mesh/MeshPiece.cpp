#include "mesh/MeshPiece.hpp"

#include <algorithm>

namespace efg {
namespace {

constexpr LocalIndex kAbsent = -1;

// The piece's cells (whole-mesh cell indices, ascending) and, marked in `in_piece`, its nodes.
std::vector<LocalIndex> piece_cells(const BackgroundMesh& mesh,
                                    const std::function<bool(LocalIndex)>& owns,
                                    std::vector<char>& in_piece) {
  std::vector<LocalIndex> cells;
  LocalIndex first = 0;  // global index of the block's first cell
  for (const auto& b : mesh.blocks) {
    const auto per = static_cast<std::size_t>(cell_node_count(b.type));
    for (std::size_t c = 0; c < b.cell_count(); ++c) {
      const auto* node = b.connectivity.data() + c * per;
      if (!owns(*std::min_element(node, node + per))) continue;
      cells.push_back(first + static_cast<LocalIndex>(c));
      for (std::size_t a = 0; a < per; ++a) in_piece[static_cast<std::size_t>(node[a])] = 1;
    }
    first += static_cast<LocalIndex>(b.cell_count());
  }
  return cells;
}

// Whole-mesh per-node values (`per` each) of the piece's nodes.
std::vector<double> restricted(const std::vector<double>& values, std::size_t per,
                               const std::vector<LocalIndex>& nodes) {
  std::vector<double> kept;
  if (values.empty()) return kept;
  kept.reserve(nodes.size() * per);
  for (auto n : nodes)
    for (std::size_t k = 0; k < per; ++k)
      kept.push_back(values[static_cast<std::size_t>(n) * per + k]);
  return kept;
}

}  // namespace

MeshPiece mesh_piece(const BackgroundMesh& mesh, const std::function<bool(LocalIndex)>& owns) {
  MeshPiece piece;
  std::vector<char> in_piece(mesh.node_count(), 0);
  piece.cells = piece_cells(mesh, owns, in_piece);
  std::vector<LocalIndex> local(mesh.node_count(), kAbsent);
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    if (in_piece[n] || owns(static_cast<LocalIndex>(n))) {
      local[n] = static_cast<LocalIndex>(piece.nodes.size());
      piece.nodes.push_back(static_cast<LocalIndex>(n));
    }

  auto& m = piece.mesh;
  m.dimension = mesh.dimension;
  m.source = mesh.source;
  m.coordinates =
      restricted(mesh.coordinates, static_cast<std::size_t>(mesh.dimension), piece.nodes);
  m.surface = restricted(mesh.surface, 3, piece.nodes);
  m.chart_plane = mesh.chart_plane;

  // Blocks keep their order, names and ids (epu matches them by id), empty ones included.
  std::vector<LocalIndex> piece_cell(mesh.cell_count(), kAbsent);
  auto next = piece.cells.begin();
  LocalIndex first = 0;
  for (const auto& b : mesh.blocks) {
    ElementBlock kept{b.name, b.id, b.type, {}, {}};
    const auto per = static_cast<std::size_t>(cell_node_count(b.type));
    const auto end = first + static_cast<LocalIndex>(b.cell_count());
    for (; next != piece.cells.end() && *next < end; ++next) {
      const auto c = static_cast<std::size_t>(*next - first);
      piece_cell[static_cast<std::size_t>(*next)] =
          static_cast<LocalIndex>(next - piece.cells.begin());
      for (std::size_t a = 0; a < per; ++a)
        kept.connectivity.push_back(local[static_cast<std::size_t>(b.connectivity[c * per + a])]);
      if (!b.thickness.empty()) kept.thickness.push_back(b.thickness[c]);
    }
    m.blocks.push_back(std::move(kept));
    first = end;
  }

  for (const auto& s : mesh.node_sets) {
    NodeSet kept{s.name, s.id, {}};
    for (auto n : s.nodes)
      if (local[static_cast<std::size_t>(n)] != kAbsent)
        kept.nodes.push_back(local[static_cast<std::size_t>(n)]);
    m.node_sets.push_back(std::move(kept));
  }
  for (const auto& s : mesh.side_sets) {
    SideSet kept{s.name, s.id, {}, {}};
    for (std::size_t i = 0; i < s.cells.size(); ++i)
      if (piece_cell[static_cast<std::size_t>(s.cells[i])] != kAbsent) {
        kept.cells.push_back(piece_cell[static_cast<std::size_t>(s.cells[i])]);
        kept.sides.push_back(s.sides[i]);
      }
    m.side_sets.push_back(std::move(kept));
  }
  return piece;
}

}  // namespace efg
