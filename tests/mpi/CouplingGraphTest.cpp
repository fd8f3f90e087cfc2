#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <algorithm>
#include <set>

#include "operators/CouplingGraph.hpp"
#include "parallel/DofMaps.hpp"
#include "parallel/NodePartition.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// The stiffness graph of cell cliques (each cell couples all its nodes, as an integration point
// couples all particles of its row): every owned row holds exactly the dofs of the nodes that
// share a cell with its node (every component of each), sorted and once; the rows of ghost nodes
// added on other ranks arrive on their owners. Expected couplings from the mesh's cells alone.
TEST(CouplingGraph, OwnedRowsHoldTheCellNeighboursOfTheirNodeSortedAndOnce) {
  const auto comm = Tpetra::getDefaultComm();
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 3, 0.1));
  auto p = partition_nodes(comm, mesh);
  p.ghosts = ghost_layer(mesh, p.owner, p.rank, 10.0);  // every other node: each cell is whole
  const int dim = 3;
  const auto maps = make_dof_maps(comm, p, dim);
  const auto& block = mesh.blocks.at(0);
  const auto per_cell = static_cast<std::size_t>(cell_node_count(block.type));

  CouplingGraph couplings(maps.overlap_nodes->getNodeNumElements());
  std::vector<std::set<GlobalOrdinal>> expected(mesh.node_count());
  for (std::size_t cell = 0; cell < block.cell_count(); ++cell) {
    std::vector<int> local;
    for (std::size_t a = 0; a < per_cell; ++a) {
      const auto node = block.connectivity[cell * per_cell + a];
      local.push_back(maps.overlap_nodes->getLocalElement(node));
      for (std::size_t b = 0; b < per_cell; ++b)
        expected[static_cast<std::size_t>(node)].insert(block.connectivity[cell * per_cell + b]);
    }
    // On 2 or 3 ranks each rank adds the cells of its parity (rank 2 repeats rank 0's), in a
    // shuffled node order: rows added on a rank that does not own them reach their owners.
    if (static_cast<int>(cell % 2) == comm->getRank() % 2 || comm->getSize() == 1) {
      std::reverse(local.begin() + 2, local.end());
      couplings.add_clique(local.data(), local.size());
    }
  }
  const auto graph = couplings.build(maps);
  ASSERT_TRUE(graph->isFillComplete());
  const auto& rows = *graph->getRowMap();
  const auto& columns = *graph->getColMap();
  for (LocalIndex i = 0; i < static_cast<LocalIndex>(rows.getNodeNumElements()); ++i) {
    const auto row = rows.getGlobalElement(i);
    const auto node = static_cast<std::size_t>(row / dim);
    std::vector<GlobalOrdinal> want;
    for (auto n : expected[node])
      for (int c = 0; c < dim; ++c) want.push_back(n * dim + c);
    Tpetra::CrsGraph<>::local_inds_host_view_type indices;
    graph->getLocalRowView(i, indices);
    std::vector<GlobalOrdinal> got;
    for (std::size_t k = 0; k < indices.extent(0); ++k) {
      if (k > 0) {
        EXPECT_LT(indices(k - 1), indices(k)) << "row " << row << " not sorted or repeated";
      }
      got.push_back(columns.getGlobalElement(indices(k)));
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want) << "row " << row;
  }
}

}  // namespace
}  // namespace efg
