#include <gtest/gtest.h>

#include <vector>

#include "mesh/MeshGenerator.hpp"
#include "parallel/NodePartition.hpp"

namespace efg {
namespace {

// The ghost layer against brute force: the nodes of the other ranks within the radius of a node
// of this one (the mesh cut at x = 0.5 between ranks 0 and 1, and a third rank owning none).
TEST(GhostLayer, ForeignNodesNearOwnedOnesByBruteForce) {
  GeneratorSpec spec;
  spec.dimension = 3;
  spec.element = CellType::hex8;
  spec.cells = {11, 6, 5};
  spec.upper = {1, 1, 1};
  spec.perturbation = 0.3;
  const auto mesh = generate_mesh(spec);
  const auto n = mesh.node_count();
  std::vector<int> owner(n);
  for (std::size_t i = 0; i < n; ++i) owner[i] = mesh.coordinates[3 * i] < 0.5 ? 0 : 1;
  for (double radius : {0.0, 0.1, 0.23, 0.6})
    for (int rank : {0, 1, 2}) {
      std::vector<LocalIndex> expected;
      for (std::size_t j = 0; j < n; ++j) {
        if (owner[j] == rank) continue;
        bool near = false;
        for (std::size_t i = 0; i < n && !near; ++i) {
          if (owner[i] != rank) continue;
          double d2 = 0;
          for (std::size_t d = 0; d < 3; ++d) {
            const double dx = mesh.coordinates[3 * i + d] - mesh.coordinates[3 * j + d];
            d2 += dx * dx;
          }
          near = radius > 0 && d2 <= radius * radius;
        }
        if (near) expected.push_back(static_cast<LocalIndex>(j));
      }
      EXPECT_EQ(ghost_layer(mesh, owner, rank, radius), expected)
          << "radius " << radius << " rank " << rank;
      if (rank == 0 && radius == 0.23) {
        EXPECT_GT(expected.size(), 0u);
      }
    }
}

}  // namespace
}  // namespace efg
