#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <limits>

#include "io/ExodusReader.hpp"
#include "io/ExodusSliceReader.hpp"
#include "io/ExodusWriter.hpp"
#include "parallel/LocalMesh.hpp"
#include "parallel/NodePartition.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// A perturbed 48 x 4 x 4 hex bar on [0, 12] x [0, 1] x [0, 1] (cells 0.25 wide) and, as a
// second body beside it, a tet block: two blocks, two cell types, node sets and side sets of
// both. Written once by rank 0.
std::string bar_file(const CommPtr& comm, const std::string& name) {
  const auto path = test::scratch_dir(name) + "/bar_np" + std::to_string(comm->getSize()) + ".e";
  if (comm->getRank() == 0) {
    GeneratorSpec bar;
    bar.upper = {12, 1, 1};
    bar.cells = {48, 4, 4};
    bar.perturbation = 0.2;
    auto mesh = generate_mesh(bar);
    GeneratorSpec tets;
    tets.element = CellType::tet4;
    tets.lower = {0, 1.5, 0};
    tets.upper = {12, 2, 0.5};
    tets.cells = {24, 1, 1};
    tets.block_name = "tets";
    append_generated(mesh, tets);
    // Sets in no particular order of their nodes or cells keep their file order: the bar's
    // "all" and "ymin" listed backwards.
    auto all = *mesh.find_node_set("all");
    std::reverse(all.nodes.begin(), all.nodes.end());
    all.name = "all_backwards";
    all.id = 100;
    mesh.node_sets.push_back(all);
    auto ymin = *mesh.find_side_set("ymin");
    std::reverse(ymin.cells.begin(), ymin.cells.end());
    std::reverse(ymin.sides.begin(), ymin.sides.end());
    ymin.name = "ymin_backwards";
    ymin.id = 100;
    mesh.side_sets.push_back(ymin);
    ExodusWriter writer(path, mesh, {}, "local mesh test");
    writer.close();
  }
  comm->barrier();
  return path;
}

// What the local mesh must be, derived from the whole mesh (read whole here, for the test only)
// and the partition partition_nodes gives it: the owned nodes, every cell with a node in the
// box around them grown by `halo`, and those cells' nodes.
struct Expected {
  std::vector<LocalIndex> nodes, cells;  // whole-mesh indices, ascending
};
Expected expected_local_mesh(const BackgroundMesh& mesh, const NodePartition& p, double halo) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::vector<double> lo(dim, std::numeric_limits<double>::max()), hi(dim, -lo[0]);
  for (auto n : p.owned)
    for (std::size_t d = 0; d < dim; ++d) {
      lo[d] = std::min(lo[d], mesh.coordinates[static_cast<std::size_t>(n) * dim + d] - halo);
      hi[d] = std::max(hi[d], mesh.coordinates[static_cast<std::size_t>(n) * dim + d] + halo);
    }
  auto inside = [&](LocalIndex n) {
    for (std::size_t d = 0; d < dim; ++d) {
      const double x = mesh.coordinates[static_cast<std::size_t>(n) * dim + d];
      if (x < lo[d] || x > hi[d]) return false;
    }
    return true;
  };
  Expected e;
  std::vector<char> keep(mesh.node_count(), 0);
  for (auto n : p.owned) keep[static_cast<std::size_t>(n)] = 1;
  LocalIndex cell = 0;
  for (const auto& b : mesh.blocks) {
    const auto per = static_cast<std::size_t>(cell_node_count(b.type));
    for (std::size_t c = 0; c < b.cell_count(); ++c, ++cell) {
      const auto* node = b.connectivity.data() + c * per;
      if (std::none_of(node, node + per, inside)) continue;
      e.cells.push_back(cell);
      for (std::size_t a = 0; a < per; ++a) keep[static_cast<std::size_t>(node[a])] = 1;
    }
  }
  for (std::size_t n = 0; n < keep.size(); ++n)
    if (keep[n]) e.nodes.push_back(static_cast<LocalIndex>(n));
  return e;
}

constexpr double kHalo = 0.3;  // a little more than one cell width

// Every rank reads only its slice; the local mesh built from the slices is exactly the part of
// the whole mesh described above: node and cell ids, coordinates, owners (the same RCB partition
// as the whole mesh's), connectivity, node and side sets in file order.
TEST(LocalMesh, IsThePartOfTheWholeMeshAroundTheOwnedNodes) {
  const auto comm = Tpetra::getDefaultComm();
  const auto path = bar_file(comm, "local_mesh");
  const auto slice = read_exodus_slice(path, comm->getRank(), comm->getSize());
  BlockExtents extents;
  const auto local = distribute_mesh(comm, slice, [&](const BlockExtents& e) {
    extents = e;
    return kHalo;
  });

  const auto whole = read_exodus_mesh(path);
  const auto p = partition_nodes(comm, whole);
  const auto expected = expected_local_mesh(whole, p, kHalo);
  const auto dim = static_cast<std::size_t>(whole.dimension);

  ASSERT_EQ(local.mesh.global.nodes.size(), expected.nodes.size());
  for (std::size_t i = 0; i < expected.nodes.size(); ++i) {
    const auto n = static_cast<std::size_t>(expected.nodes[i]);
    ASSERT_EQ(local.mesh.global.nodes[i], static_cast<GlobalIndex>(n));
    EXPECT_EQ(local.owner[i], p.owner[n]);
    for (std::size_t d = 0; d < dim; ++d)
      EXPECT_EQ(local.mesh.coordinates[i * dim + d], whole.coordinates[n * dim + d]);
  }
  ASSERT_EQ(local.mesh.global.cells.size(), expected.cells.size());
  for (std::size_t c = 0; c < expected.cells.size(); ++c) {
    ASSERT_EQ(local.mesh.global.cells[c], expected.cells[c]);
    const auto [block, index] = whole.locate_cell(static_cast<std::size_t>(expected.cells[c]));
    const auto [local_block, local_index] = local.mesh.locate_cell(c);
    EXPECT_EQ(local_block->name, block->name);
    const auto per = static_cast<std::size_t>(cell_node_count(block->type));
    for (std::size_t a = 0; a < per; ++a)
      EXPECT_EQ(
          local.mesh.global
              .nodes[static_cast<std::size_t>(local_block->connectivity[local_index * per + a])],
          block->connectivity[index * per + a]);
  }
  ASSERT_EQ(local.mesh.node_sets.size(), whole.node_sets.size());
  for (std::size_t s = 0; s < whole.node_sets.size(); ++s) {
    std::vector<GlobalIndex> want, got;
    for (auto n : whole.node_sets[s].nodes)
      if (std::binary_search(expected.nodes.begin(), expected.nodes.end(), n)) want.push_back(n);
    for (auto n : local.mesh.node_sets[s].nodes)
      got.push_back(local.mesh.global.nodes[static_cast<std::size_t>(n)]);
    EXPECT_EQ(got, want) << whole.node_sets[s].name;
    EXPECT_EQ(local.mesh.node_sets[s].name, whole.node_sets[s].name);
  }
  ASSERT_EQ(local.mesh.side_sets.size(), whole.side_sets.size());
  for (std::size_t s = 0; s < whole.side_sets.size(); ++s) {
    std::vector<std::pair<GlobalIndex, int>> want, got;
    const auto& set = whole.side_sets[s];
    for (std::size_t i = 0; i < set.cells.size(); ++i)
      if (std::binary_search(expected.cells.begin(), expected.cells.end(), set.cells[i]))
        want.emplace_back(set.cells[i], set.sides[i]);
    const auto& mine = local.mesh.side_sets[s];
    for (std::size_t i = 0; i < mine.cells.size(); ++i)
      got.emplace_back(local.mesh.global.cells[static_cast<std::size_t>(mine.cells[i])],
                       mine.sides[i]);
    EXPECT_EQ(got, want) << set.name;
  }
  // The blocks' largest cell extents, by hand: hex cells 0.25 wide whose nodes move by up to 20 %
  // of the spacing (at most 0.35 along the bar), tets in cells 0.5 x 0.5 x 0.5.
  ASSERT_EQ(extents.size(), 2u);
  EXPECT_GT(extents[0][0], 0.25);
  EXPECT_LE(extents[0][0], 0.35);
  EXPECT_DOUBLE_EQ(extents[1][0], 0.5);
  EXPECT_DOUBLE_EQ(extents[1][2], 0.5);
}

// No rank holds the whole mesh: the 49 x 5 x 5-node bar is cut by RCB across its length, so a
// rank owns about n / p nodes, its cut possibly through a plane of 25 (nodes move by up to 0.05
// along the bar). Beyond the last plane it owns whole, the box grown by 0.3 reaches the partly
// owned plane and the next (0.25 + 0.05 away from the partly owned one at least 0.2 away), and the
// cells touching those bring one plane more: at most 3 planes per cut, 2 cuts for a middle rank.
// Bound: n_bar / p + 6 planes + all of the tets' 25 x 2 x 2 nodes; the slice read holds n / p
// nodes (rounded up).
TEST(LocalMesh, HoldsAboutOneRanksShareOfTheMesh) {
  const auto comm = Tpetra::getDefaultComm();
  const auto path = bar_file(comm, "local_mesh_share");
  const auto p = static_cast<std::size_t>(comm->getSize());
  const auto slice = read_exodus_slice(path, comm->getRank(), comm->getSize());
  const auto local = distribute_mesh(comm, slice, [](const BlockExtents&) { return kHalo; });
  const std::size_t bar_nodes = 49 * 5 * 5, tet_nodes = 25 * 2 * 2, plane = 25;
  const std::size_t nodes = bar_nodes + tet_nodes;
  EXPECT_LE(slice.read_node_count(), nodes / p + 1);
  if (p > 1) {
    EXPECT_LE(local.mesh.node_count(), bar_nodes / p + 6 * plane + tet_nodes);
  }
  EXPECT_EQ(local.mesh.coordinates.size(), 3 * local.mesh.global.nodes.size());
  EXPECT_EQ(local.owner.size(), local.mesh.global.nodes.size());
  std::size_t owned = 0;
  for (auto o : local.owner) owned += o == comm->getRank() ? 1 : 0;
  std::size_t total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &owned, &total);
  EXPECT_EQ(total, nodes);  // every node owned once
}

}  // namespace
}  // namespace efg
