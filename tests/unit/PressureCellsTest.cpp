// The pressure cells of mixed u-p parts (discretization/PressureCells): vertex patches of the
// background cells. Expected values are counted by hand on structured meshes.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "discretization/PressureCells.hpp"
#include "mesh/MeshGenerator.hpp"

namespace efg {
namespace {

GeneratorSpec grid(CellType element, int nx, int ny, int nz = 0) {
  GeneratorSpec s;
  s.dimension = nz > 0 ? 3 : 2;
  s.element = element;
  s.cells = {nx, ny, nz > 0 ? nz : 1};
  s.upper = {static_cast<double>(nx), static_cast<double>(ny), static_cast<double>(nz)};
  return s;
}

PartSpec part_of(const BackgroundMesh& mesh, PressureCellChoice choice) {
  PartSpec p;
  p.name = "p";
  p.blocks = {mesh.blocks.front().name};
  p.formulation = PartFormulation::mixed_up;
  p.pressure_cells = choice;
  return p;
}

// Every cell of the part in exactly one group, and `group` the inverse of the lists.
void expect_partition(const BackgroundMesh& mesh, const PressureCells& g) {
  std::vector<int> seen(mesh.cell_count(), 0);
  for (std::size_t k = 0; k < g.size(); ++k)
    for (auto i = g.offsets[k]; i < g.offsets[k + 1]; ++i) {
      ++seen[g.cells[i]];
      EXPECT_EQ(g.group[g.cells[i]], k);
    }
  for (int s : seen) EXPECT_EQ(s, 1);
}

// The integer corner (lowest x, y, z of its nodes) of every cell of a unit grid.
std::array<int, 3> corner(const BackgroundMesh& mesh, std::size_t cell) {
  const auto [block, local] = mesh.locate_cell(cell);
  const auto npc = static_cast<std::size_t>(cell_node_count(block->type));
  std::array<int, 3> c{1 << 20, 1 << 20, 1 << 20};
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  for (std::size_t a = 0; a < npc; ++a)
    for (std::size_t d = 0; d < dim; ++d)
      c[d] = std::min(
          c[d],
          static_cast<int>(std::lround(
              mesh.coordinates
                  [static_cast<std::size_t>(block->connectivity[local * npc + a]) * dim + d])));
  return c;
}

TEST(PressureCells, EvenQuadGridTilesInTwoByTwo) {
  const auto mesh = generate_mesh(grid(CellType::quad4, 6, 4));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  expect_partition(mesh, g);
  ASSERT_EQ(g.size(), 6u);  // 3 x 2 patches
  for (std::size_t k = 0; k < g.size(); ++k) {
    ASSERT_EQ(g.offsets[k + 1] - g.offsets[k], 4u);
    std::set<std::array<int, 3>> block;
    for (auto i = g.offsets[k]; i < g.offsets[k + 1]; ++i) {
      auto c = corner(mesh, g.cells[i]);
      block.insert({c[0] / 2, c[1] / 2, 0});
    }
    EXPECT_EQ(block.size(), 1u) << "patch " << k << " spans two aligned 2 x 2 blocks";
  }
}

TEST(PressureCells, OddCountsJoinANeighbouringPatch) {
  // 5 x 3 cells: the interior nodes (1,1), (3,1) take 2 x 2 patches; the column x = 4 and the
  // row y = 2 join them: 15 cells in 2 groups of 6 to 9 cells.
  const auto mesh = generate_mesh(grid(CellType::quad4, 5, 3));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  expect_partition(mesh, g);
  ASSERT_EQ(g.size(), 2u);
  for (std::size_t k = 0; k < g.size(); ++k) {
    EXPECT_GE(g.offsets[k + 1] - g.offsets[k], 6u);
    EXPECT_LE(g.offsets[k + 1] - g.offsets[k], 9u);
  }
}

TEST(PressureCells, AStripOneCellThickPairsItsCells) {
  // No interior node: cells start groups with their free face neighbours.
  const auto mesh = generate_mesh(grid(CellType::quad4, 6, 1));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  expect_partition(mesh, g);
  EXPECT_EQ(g.size(), 3u);
  const auto odd = generate_mesh(grid(CellType::quad4, 5, 1));  // {0, 1}, {2, 3} + the lone 4
  const auto h = pressure_cells(odd, part_of(odd, PressureCellChoice::patch));
  expect_partition(odd, h);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(h.offsets[1], 2u);
}

TEST(PressureCells, HexGridTilesInTwoByTwoByTwo) {
  const auto mesh = generate_mesh(grid(CellType::hex8, 4, 2, 2));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  expect_partition(mesh, g);
  ASSERT_EQ(g.size(), 2u);
  for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(g.offsets[k + 1] - g.offsets[k], 8u);
}

TEST(PressureCells, TrianglesGroupAroundInteriorVertices) {
  const auto mesh = generate_mesh(grid(CellType::tri3, 4, 4));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  expect_partition(mesh, g);
  EXPECT_LT(g.size(), mesh.cell_count() / 3);  // several triangles per pressure
  for (std::size_t k = 0; k < g.size(); ++k) EXPECT_GE(g.offsets[k + 1] - g.offsets[k], 3u);
}

TEST(PressureCells, SingleCellsAreOneGroupEach) {
  const auto mesh = generate_mesh(grid(CellType::quad4, 3, 2));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::cell));
  expect_partition(mesh, g);
  EXPECT_EQ(g.size(), 6u);
}

TEST(PressureCells, OwnersAndDiameter) {
  const auto mesh = generate_mesh(grid(CellType::quad4, 4, 2));
  const auto g = pressure_cells(mesh, part_of(mesh, PressureCellChoice::patch));
  // Nodes 0..14 (5 per row); rank 1 owns nodes with x >= 2: the right patch's lowest node is 2.
  std::vector<int> owner(mesh.node_count());
  for (std::size_t n = 0; n < owner.size(); ++n) owner[n] = mesh.coordinates[n * 2] >= 2 ? 1 : 0;
  const auto zero = owned_groups(mesh, g, owner, 0), one = owned_groups(mesh, g, owner, 1);
  EXPECT_EQ(zero.size(), 1u);
  EXPECT_EQ(one.size(), 1u);
  EXPECT_NEAR(largest_group_diameter(mesh, g), std::sqrt(8.0), 1e-14);  // the 2 x 2 diagonal
}

}  // namespace
}  // namespace efg
