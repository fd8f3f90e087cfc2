// Support half-widths from the nodal spacing measures (discretization/ParticleCloud.hpp), on
// lattices of cells sheared against the axes where the measures differ; expected values worked
// out by hand from the lattice vectors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "discretization/ParticleCloud.hpp"
#include "mesh/CellTopology.hpp"

namespace efg {
namespace {

// Columns of nodes 3 apart in x, rows v apart in y, each column shifted up by s from the last:
// node (i, j) at (3 i, s i + v j). Every cell is the parallelogram spanned by (3, s) and (0, v).
constexpr double kColumn = 3.0, kShear = 2.75, kRow = 1.0;

BackgroundMesh sheared_quads(int n) {
  BackgroundMesh mesh;
  mesh.dimension = 2;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      mesh.coordinates.push_back(kColumn * i);
      mesh.coordinates.push_back(kShear * i + kRow * j);
    }
  ElementBlock block;
  block.name = "block_1";
  block.type = CellType::quad4;
  auto node = [n](int i, int j) { return static_cast<LocalIndex>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (auto k : {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)})
        block.connectivity.push_back(k);
  mesh.blocks.push_back(block);
  return mesh;
}

// The same lattice extruded: node (i, j, k) at (3 i, s i + v j, w k).
constexpr double kLayer = 0.5;

BackgroundMesh sheared_hexes(int n) {
  BackgroundMesh mesh;
  mesh.dimension = 3;
  auto node = [n](int i, int j, int k) {
    return static_cast<LocalIndex>((k * (n + 1) + i) * (n + 1) + j);
  };
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        mesh.coordinates.push_back(kColumn * i);
        mesh.coordinates.push_back(kShear * i + kRow * j);
        mesh.coordinates.push_back(kLayer * k);
      }
  ElementBlock block;
  block.name = "block_1";
  block.type = CellType::hex8;
  for (int k = 0; k < n; ++k)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int layer : {k, k + 1})
          for (auto m : {node(i, j, layer), node(i + 1, j, layer), node(i + 1, j + 1, layer),
                         node(i, j + 1, layer)})
            block.connectivity.push_back(m);
  mesh.blocks.push_back(block);
  return mesh;
}

SectionSpec section(SpacingMeasure spacing, double dilation) {
  SectionSpec s;
  s.spacing = spacing;
  s.dilation = {dilation};
  return s;
}

TEST(SupportSize, EdgesMeasureTheRowsOfAShearedLattice) {
  const auto mesh = sheared_quads(4);
  const std::size_t centre = 2 * 5 + 2;  // node (2, 2): every cell around it is interior
  // The x edge (3, s) runs mainly along x (3 > s), the y edge (0, v) along y: h = (3, v).
  const auto edges = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::edges, 2.0));
  EXPECT_NEAR(edges[centre * 2 + 0], 2.0 * kColumn, 1e-14);
  EXPECT_NEAR(edges[centre * 2 + 1], 2.0 * kRow, 1e-14);
  // The cells' extent in y adds the shear of the x edges: h = (3, s + v).
  const auto cells = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::cells, 2.0));
  EXPECT_NEAR(cells[centre * 2 + 0], 2.0 * kColumn, 1e-14);
  EXPECT_NEAR(cells[centre * 2 + 1], 2.0 * (kShear + kRow), 1e-14);
  // A sphere takes the largest direction of its own measure.
  auto sphere = section(SpacingMeasure::edges, 2.0);
  sphere.support = SupportShape::sphere;
  const auto round = support_sizes(mesh, {"block_1"}, sphere);
  EXPECT_NEAR(round[centre * 2 + 1], 2.0 * kColumn, 1e-14);
}

TEST(SupportSize, EdgesMeasureTheRowsOfAShearedHexLattice) {
  const auto mesh = sheared_hexes(3);
  const std::size_t centre = (1 * 4 + 1) * 4 + 1;  // node (1, 1, 1)
  const auto edges = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::edges, 1.5));
  EXPECT_NEAR(edges[centre * 3 + 0], 1.5 * kColumn, 1e-14);
  EXPECT_NEAR(edges[centre * 3 + 1], 1.5 * kRow, 1e-14);
  EXPECT_NEAR(edges[centre * 3 + 2], 1.5 * kLayer, 1e-14);
  const auto cells = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::cells, 1.5));
  EXPECT_NEAR(cells[centre * 3 + 1], 1.5 * (kShear + kRow), 1e-14);
}

TEST(SupportSize, EdgesEqualCellsOnAxisAlignedCells) {
  // Rows and columns of a rectangle's lattice (s = 0): both measures are the cell sides.
  auto mesh = sheared_quads(3);
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    mesh.coordinates[2 * n + 1] -= kShear * mesh.coordinates[2 * n] / kColumn;
  const auto edges = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::edges, 1.7));
  const auto cells = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::cells, 1.7));
  for (std::size_t k = 0; k < edges.size(); ++k) EXPECT_NEAR(edges[k], cells[k], 1e-13) << k;
}

TEST(SupportSize, EdgesOfASquareTurnedByHalfARightAngleCountBothAxes) {
  // Both edges of a square turned by 45 degrees run as much along x as along y: both count, and
  // each spans h / sqrt(2) along either axis (the extent spans h sqrt(2)).
  BackgroundMesh mesh;
  mesh.dimension = 2;
  const double r = 1.0 / std::sqrt(2.0);
  mesh.coordinates = {0, 0, r, r, 0, 2 * r, -r, r};
  ElementBlock block;
  block.name = "block_1";
  block.type = CellType::quad4;
  block.connectivity = {0, 1, 2, 3};
  mesh.blocks.push_back(block);
  const auto a = support_sizes(mesh, {"block_1"}, section(SpacingMeasure::edges, 2.0));
  for (double ad : a) EXPECT_NEAR(ad, 2.0 * r, 1e-14);
}

TEST(CellEdges, EachEdgeOnce) {
  const std::vector<std::pair<CellType, std::size_t>> expected = {{CellType::quad4, 4},
                                                                  {CellType::tri3, 3},
                                                                  {CellType::hex8, 12},
                                                                  {CellType::tet4, 6},
                                                                  {CellType::wedge6, 9}};
  for (const auto& [type, count] : expected) {
    auto edges = cell_edges(type);
    EXPECT_EQ(edges.size(), count) << cell_scene_name(type);
    for (auto& e : edges) {
      EXPECT_LT(e[0], e[1]);
      EXPECT_LT(e[1], cell_node_count(type));
    }
    std::sort(edges.begin(), edges.end());
    EXPECT_TRUE(std::adjacent_find(edges.begin(), edges.end()) == edges.end());
  }
  // A hex's edges join nodes that differ in one reference coordinate: (0,1) yes, (0,2) no.
  const auto hex = cell_edges(CellType::hex8);
  EXPECT_NE(std::find(hex.begin(), hex.end(), std::array<int, 2>{0, 4}), hex.end());
  EXPECT_EQ(std::find(hex.begin(), hex.end(), std::array<int, 2>{0, 2}), hex.end());
  EXPECT_EQ(std::find(hex.begin(), hex.end(), std::array<int, 2>{0, 6}), hex.end());
}

}  // namespace
}  // namespace efg
