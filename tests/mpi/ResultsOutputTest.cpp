#include <gtest/gtest.h>

#include <exodusII.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>

#include "io/ExodusReader.hpp"
#include "io/ResultsOutput.hpp"
#include "parallel/DofMaps.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// A perturbed hex8 box partitioned over the ranks, and a results path for the rank count.
struct PartitionedBox {
  explicit PartitionedBox(const std::string& name)
      : comm(Tpetra::getDefaultComm()),
        mesh(generate_mesh(test::box_spec(CellType::hex8, 3, 0.2))),
        p(partition_nodes(comm, mesh)),
        maps(make_dof_maps(comm, p, 3)),
        path(test::scratch_dir(name) + "/np" + std::to_string(comm->getSize()) + ".e") {}
  CommPtr comm;
  BackgroundMesh mesh;
  NodePartition p;
  DofMaps maps;
  std::string path;
};

// Each rank writes values of its own particles; the gathered file must equal what a serial run
// would write: value = f(global id), and the owner column matches the partition.
TEST(ResultsOutput, GathersOwnedValuesIntoOneFile) {
  const PartitionedBox box("gather");
  const auto& [comm, mesh, p, maps, path] = box;
  ResultsOutput output(comm, path, mesh, maps.owned_nodes,
                       OutputLayout{{"f", "owner_rank"}, {}, {"t2"}}, "gather");
  for (int step = 0; step < 2; ++step) {
    ResultsOutput::MultiVector values(maps.owned_nodes, 2);
    {
      auto v = values.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t i = 0; i < p.owned.size(); ++i) {
        v(i, 0) = 0.5 * p.owned[i] + step;
        v(i, 1) = p.rank;
      }
    }
    output.write(step * 0.5, values, {step * 2.0});
  }
  output.close();
  if (comm->getRank() == 0) {
    const auto r = read_exodus_results(path);
    ASSERT_EQ(r.times.size(), 2u);
    for (std::size_t step = 0; step < 2; ++step) {
      for (std::size_t n = 0; n < mesh.node_count(); ++n) {
        EXPECT_EQ(r.nodal.at("f")[step][n],
                  0.5 * static_cast<double>(n) + static_cast<double>(step));
        EXPECT_EQ(r.nodal.at("owner_rank")[step][n], p.owner[n]);
      }
      EXPECT_EQ(r.global.at("t2")[step], 2.0 * static_cast<double>(step));
    }
  }
}

// The whole mesh's (0-based) index of every node or cell of an Exodus file, from its id map.
std::vector<std::int64_t> id_map(const std::string& path, ex_entity_type type, std::size_t count) {
  int cpu = 8, io = 8;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpu, &io, &version);
  EXPECT_GE(id, 0) << path;
  std::vector<std::int64_t> ids(count);
  if (count > 0) {
    EXPECT_EQ(ex_get_id_map(id, type, ids.data()), 0);
  }
  ex_close(id);
  for (auto& i : ids) --i;
  return ids;
}

// One file per rank: each rank's piece holds, under the whole mesh's ids (its id maps), the
// coordinates, the values of f = 0.5 id + step at every node of its cells (its own and those it
// imported) and g = 2 id at its cells, which are the cells whose lowest node it owns; over the
// ranks every cell is written exactly once (what SEACAS epu needs to join them).
TEST(ResultsOutput, WritesOnePieceOfTheMeshPerRankUnderTheWholeMeshIds) {
  const PartitionedBox box("pieces");
  const auto& [comm, mesh, p, maps, path] = box;
  // Which rank provides a cell's values does not matter: cells by index modulo the rank count,
  // so that many reach their piece from another rank.
  std::vector<GlobalOrdinal> provided;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    if (static_cast<int>(c % static_cast<std::size_t>(comm->getSize())) == comm->getRank())
      provided.push_back(static_cast<GlobalOrdinal>(c));
  ResultsOutput output(comm, path, mesh, maps.owned_nodes, OutputLayout{{"f"}, {"g"}, {"t2"}},
                       "pieces", provided, true);
  for (int step = 0; step < 2; ++step) {
    ResultsOutput::MultiVector values(maps.owned_nodes, 1);
    ResultsOutput::MultiVector cells(output.cell_map(), 1);
    {
      auto v = values.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t i = 0; i < p.owned.size(); ++i) v(i, 0) = 0.5 * p.owned[i] + step;
      auto c = cells.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t i = 0; i < provided.size(); ++i)
        c(i, 0) = 2.0 * static_cast<double>(provided[i]);
    }
    output.write(step * 0.5, values, {step * 2.0}, &cells);
  }
  output.close();

  // (one rank's piece is the whole mesh: it writes the one file; Exodus then makes up the maps)
  const auto file = comm->getSize() > 1 ? piece_path(path, comm->getSize(), comm->getRank()) : path;
  const auto piece = read_exodus_mesh(file);
  const auto r = read_exodus_results(file);
  const auto nodes = id_map(file, EX_NODE_MAP, piece.node_count());
  const auto cells = id_map(file, EX_ELEM_MAP, piece.cell_count());
  // the cells: those whose lowest node is owned here, ascending
  std::vector<std::int64_t> expected_cells;
  const auto per = static_cast<std::size_t>(cell_node_count(CellType::hex8));
  const auto& conn = mesh.blocks.at(0).connectivity;
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    if (p.owner[static_cast<std::size_t>(
            *std::min_element(&conn[c * per], &conn[c * per] + per))] == comm->getRank())
      expected_cells.push_back(static_cast<std::int64_t>(c));
  EXPECT_EQ(cells, expected_cells);
  ASSERT_EQ(r.times.size(), 2u);
  for (std::size_t k = 0; k < piece.node_count(); ++k) {
    const auto n = static_cast<std::size_t>(nodes[k]);
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(piece.coordinates[3 * k + static_cast<std::size_t>(d)],
                mesh.coordinates[3 * n + static_cast<std::size_t>(d)]);
    for (std::size_t step = 0; step < 2; ++step)
      EXPECT_EQ(r.nodal.at("f")[step][k], 0.5 * static_cast<double>(n) + static_cast<double>(step));
  }
  for (std::size_t k = 0; k < piece.cell_count(); ++k) {
    for (std::size_t a = 0; a < per; ++a)  // the cell's nodes, through the node map
      EXPECT_EQ(nodes[static_cast<std::size_t>(piece.blocks[0].connectivity[k * per + a])],
                conn[static_cast<std::size_t>(cells[k]) * per + a]);
    EXPECT_EQ(r.element.at("g")[1][k], 2.0 * static_cast<double>(cells[k]));
  }
  EXPECT_EQ(r.global.at("t2")[1], 2.0);
  // every cell in exactly one piece
  std::size_t total = 0, mine = piece.cell_count();
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(total));
  EXPECT_EQ(total, mesh.cell_count());
}

}  // namespace
}  // namespace efg
