#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "parallel/NodePartition.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// Brute force: every node of another rank within the radius of one of mine.
std::vector<LocalIndex> brute_force_ghosts(const BackgroundMesh& mesh,
                                           const std::vector<int>& owner, int rank, double radius) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::vector<LocalIndex> ghosts;
  for (std::size_t j = 0; j < mesh.node_count(); ++j) {
    if (owner[j] == rank) continue;
    for (std::size_t i = 0; i < mesh.node_count(); ++i) {
      if (owner[i] != rank) continue;
      double d2 = 0;
      for (std::size_t d = 0; d < dim; ++d) {
        const double dx = mesh.coordinates[i * dim + d] - mesh.coordinates[j * dim + d];
        d2 += dx * dx;
      }
      if (d2 <= radius * radius) {
        ghosts.push_back(static_cast<LocalIndex>(j));
        break;
      }
    }
  }
  return ghosts;
}

TEST(GhostLayer, ContainsExactlyTheNodesWithinTheRadius) {
  const auto comm = Tpetra::getDefaultComm();
  for (auto type : {CellType::quad4, CellType::hex8}) {
    const auto mesh = generate_mesh(test::box_spec(type, 6, 0.3));
    const auto p = partition_nodes(comm, mesh);
    for (double radius : {0.1, 1.0 / 6.0 * 1.5, 0.45}) {
      const auto ghosts = ghost_layer(mesh, p.owner, p.rank, radius);
      EXPECT_EQ(ghosts, brute_force_ghosts(mesh, p.owner, p.rank, radius))
          << cell_scene_name(type) << " radius " << radius << " rank " << p.rank;
      if (comm->getSize() == 1) {
        EXPECT_TRUE(ghosts.empty());
      }
    }
  }
}

TEST(GhostLayer, GrowsWithTheRadius) {
  const auto comm = Tpetra::getDefaultComm();
  if (comm->getSize() == 1) GTEST_SKIP() << "no ghosts on one rank";
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 6, 0.1));
  const auto p = partition_nodes(comm, mesh);
  const auto small = ghost_layer(mesh, p.owner, p.rank, 0.2);
  const auto large = ghost_layer(mesh, p.owner, p.rank, 0.4);
  EXPECT_FALSE(small.empty());
  EXPECT_GT(large.size(), small.size());
  EXPECT_TRUE(std::includes(large.begin(), large.end(), small.begin(), small.end()));
}

}  // namespace
}  // namespace efg
