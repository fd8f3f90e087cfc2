#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "mesh/MeshGenerator.hpp"
#include "mesh/MeshPiece.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// Two ranks' pieces of a perturbed quad mesh, nodes owned by a cut at x = 0.45 (not along a
// cell edge): every cell lies in the piece owning its lowest node, exactly once; a piece's nodes
// are its owned nodes and its cells' nodes, ascending; coordinates, connectivity and the node and
// side sets read through the maps equal the whole mesh's.
TEST(MeshPieceOf, APerturbedQuadMeshSplitsIntoPiecesThatJoinToTheWholeMesh) {
  const auto mesh = generate_mesh(test::box_spec(CellType::quad4, 4, 0.2));
  const auto left = [&](LocalIndex n) {
    return mesh.coordinates[2 * static_cast<std::size_t>(n)] < 0.45;
  };
  const MeshPiece pieces[2] = {mesh_piece(mesh, left),
                               mesh_piece(mesh, [&](LocalIndex n) { return !left(n); })};
  const auto& conn = mesh.blocks.at(0).connectivity;
  std::multiset<LocalIndex> cells;
  std::set<std::pair<std::string, LocalIndex>> set_nodes;
  std::set<std::tuple<std::string, LocalIndex, int>> set_sides;
  for (int r = 0; r < 2; ++r) {
    const auto& piece = pieces[r];
    const auto owns = [&](LocalIndex n) { return (r == 0) == left(n); };
    EXPECT_TRUE(std::is_sorted(piece.nodes.begin(), piece.nodes.end()));
    for (std::size_t n = 0; n < mesh.node_count(); ++n)
      if (owns(static_cast<LocalIndex>(n))) {
        EXPECT_TRUE(
            std::binary_search(piece.nodes.begin(), piece.nodes.end(), static_cast<LocalIndex>(n)));
      }
    ASSERT_EQ(piece.mesh.node_count(), piece.nodes.size());
    for (std::size_t k = 0; k < piece.nodes.size(); ++k)
      for (std::size_t d = 0; d < 2; ++d)
        EXPECT_EQ(piece.mesh.coordinates[2 * k + d],
                  mesh.coordinates[2 * static_cast<std::size_t>(piece.nodes[k]) + d]);
    ASSERT_EQ(piece.mesh.cell_count(), piece.cells.size());
    const auto& local = piece.mesh.blocks.at(0).connectivity;
    for (std::size_t k = 0; k < piece.cells.size(); ++k) {
      const auto c = static_cast<std::size_t>(piece.cells[k]);
      EXPECT_TRUE(owns(*std::min_element(&conn[4 * c], &conn[4 * c] + 4))) << "cell " << c;
      for (std::size_t a = 0; a < 4; ++a)
        EXPECT_EQ(piece.nodes[static_cast<std::size_t>(local[4 * k + a])], conn[4 * c + a]);
      cells.insert(piece.cells[k]);
    }
    for (const auto& s : piece.mesh.node_sets)
      for (auto n : s.nodes) set_nodes.emplace(s.name, piece.nodes[static_cast<std::size_t>(n)]);
    for (const auto& s : piece.mesh.side_sets)
      for (std::size_t i = 0; i < s.cells.size(); ++i)
        set_sides.emplace(s.name, piece.cells[static_cast<std::size_t>(s.cells[i])], s.sides[i]);
  }
  EXPECT_EQ(cells.size(), mesh.cell_count());
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    EXPECT_EQ(cells.count(static_cast<LocalIndex>(c)), 1u) << "cell " << c;
  std::set<std::pair<std::string, LocalIndex>> whole_nodes;
  for (const auto& s : mesh.node_sets)
    for (auto n : s.nodes) whole_nodes.emplace(s.name, n);
  EXPECT_EQ(set_nodes, whole_nodes);
  std::set<std::tuple<std::string, LocalIndex, int>> whole_sides;
  for (const auto& s : mesh.side_sets)
    for (std::size_t i = 0; i < s.cells.size(); ++i)
      whole_sides.emplace(s.name, s.cells[i], s.sides[i]);
  EXPECT_FALSE(whole_sides.empty());
  EXPECT_EQ(set_sides, whole_sides);
}

}  // namespace
}  // namespace efg
