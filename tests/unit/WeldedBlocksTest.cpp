// Welding the nodes of a rigid body's blocks (model/WeldedBlocks): two hex8 cells of a bar, each
// with nodes of its own where they meet (as a tube's cells meet at its seam, or two blocks
// meshed node to node), one of them off by 1e-13 of the bar's size (the round-off of a map that
// closes on itself). Welded, the face they share is no boundary: the bar's 10 outer quadrilateral
// faces, 20 triangles, enclose it; unwelded there are 12 faces (the shared one twice).
#include <gtest/gtest.h>

#include "discretization/OrientedFacets.hpp"
#include "model/WeldedBlocks.hpp"

namespace {

efg::BackgroundMesh two_cells(double offset) {
  efg::BackgroundMesh mesh;
  mesh.dimension = 3;
  // cell a: [0, 1]^3, cell b: [1, 2] x [0, 1]^2, nodes of its own (8 .. 15)
  for (int cell = 0; cell < 2; ++cell)
    for (int k = 0; k < 8; ++k) {
      const double x = cell + ((k == 1 || k == 2 || k == 5 || k == 6) ? 1.0 : 0.0);
      const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? 1.0 : 0.0;
      const double z = k >= 4 ? 1.0 : 0.0;
      const bool shared_face = (cell == 0 && x == 1.0) || (cell == 1 && x == 1.0);
      mesh.coordinates.insert(mesh.coordinates.end(),
                              {x + (cell == 1 && shared_face ? offset : 0.0), y, z});
    }
  efg::ElementBlock block;
  block.name = "bar";
  block.type = efg::CellType::hex8;
  for (int n = 0; n < 16; ++n) block.connectivity.push_back(n);
  mesh.blocks.push_back(block);
  return mesh;
}

TEST(WeldedBlocks, NodesAtTheSamePlaceAreOne) {
  const auto mesh = two_cells(2e-13);
  EXPECT_EQ(efg::oriented_boundary_facets(mesh, {"bar"}).count(), 24u);
  const auto welded = efg::welded_blocks(mesh, {"bar"});
  EXPECT_EQ(welded.node_count(), 12u);
  EXPECT_EQ(efg::oriented_boundary_facets(welded, {"bar"}).count(), 20u);
  // a gap of 1e-6 of the bar's size is no weld
  EXPECT_EQ(efg::welded_blocks(two_cells(2e-6), {"bar"}).node_count(), 16u);
}

}  // namespace
