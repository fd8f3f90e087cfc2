#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "parallel/DofMaps.hpp"
#include "parallel/NodePartition.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

class PartitionByElement : public ::testing::TestWithParam<CellType> {};

TEST_P(PartitionByElement, EveryNodeOwnedExactlyOnce) {
  const auto comm = Tpetra::getDefaultComm();
  const auto mesh = generate_mesh(test::box_spec(GetParam(), 5, 0.2));
  const auto p = partition_nodes(comm, mesh);
  const auto n = mesh.node_count();
  ASSERT_EQ(p.owner.size(), n);
  // Each rank counts the nodes it owns; summed over ranks every node is owned once.
  std::vector<int> mine(n, 0), total(n, 0);
  for (auto node : p.owned) mine[static_cast<std::size_t>(node)] = 1;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, static_cast<int>(n), mine.data(), total.data());
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(total[i], 1) << "node " << i;
  // The owner map is the same on every rank and agrees with the owned lists.
  std::vector<int> max_owner(n), min_owner(n);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(n), p.owner.data(),
                     max_owner.data());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, static_cast<int>(n), p.owner.data(),
                     min_owner.data());
  EXPECT_EQ(max_owner, p.owner);
  EXPECT_EQ(min_owner, p.owner);
  for (auto node : p.owned) EXPECT_EQ(p.owner[static_cast<std::size_t>(node)], comm->getRank());
  // RCB balances counts: no rank holds more than its share plus a few percent.
  const double share = static_cast<double>(n) / comm->getSize();
  EXPECT_LE(static_cast<double>(p.owned.size()), 1.1 * share + 1);
  EXPECT_GE(static_cast<double>(p.owned.size()), 0.9 * share - 1);
}

INSTANTIATE_TEST_SUITE_P(AllElements, PartitionByElement,
                         ::testing::Values(CellType::quad4, CellType::tri3, CellType::hex8,
                                           CellType::tet4, CellType::wedge6),
                         [](const auto& p) { return cell_scene_name(p.param); });

TEST(Partition, IsDeterministic) {
  const auto comm = Tpetra::getDefaultComm();
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 4, 0.2));
  EXPECT_EQ(partition_nodes(comm, mesh).owner, partition_nodes(comm, mesh).owner);
}

TEST(DofMaps, OwnedAndOverlapMapsMatchThePartition) {
  const auto comm = Tpetra::getDefaultComm();
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 3));
  auto p = partition_nodes(comm, mesh);
  p.ghosts = ghost_layer(mesh, p.owner, p.rank, 0.5);
  const auto maps = make_dof_maps(comm, p, 3);
  EXPECT_EQ(maps.owned_nodes->getGlobalNumElements(), mesh.node_count());
  EXPECT_EQ(maps.owned_dofs->getGlobalNumElements(), 3 * mesh.node_count());
  EXPECT_TRUE(maps.owned_nodes->isOneToOne());
  EXPECT_EQ(maps.overlap_nodes->getNodeNumElements(), p.owned.size() + p.ghosts.size());
  EXPECT_EQ(maps.overlap_dofs->getNodeNumElements(), 3 * (p.owned.size() + p.ghosts.size()));
  // Owned first, then ghosts; dof gid = 3 * node + component.
  const auto overlap = maps.overlap_dofs->getNodeElementList();
  for (std::size_t i = 0; i < p.owned.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(overlap[3 * i + static_cast<std::size_t>(c)], 3LL * p.owned[i] + c);
  for (std::size_t g = 0; g < p.ghosts.size(); ++g)
    EXPECT_EQ(overlap[3 * (p.owned.size() + g)], 3LL * p.ghosts[g]);
}

}  // namespace
}  // namespace efg
