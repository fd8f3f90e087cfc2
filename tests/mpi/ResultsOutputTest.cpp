#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "io/ExodusReader.hpp"
#include "io/ResultsOutput.hpp"
#include "parallel/DofMaps.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// Each rank writes values of its own particles; the gathered file must equal what a serial run
// would write: value = f(global id), and the owner column matches the partition.
TEST(ResultsOutput, GathersOwnedValuesIntoOneFile) {
  const auto comm = Tpetra::getDefaultComm();
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 3, 0.2));
  const auto p = partition_nodes(comm, mesh);
  const auto maps = make_dof_maps(comm, p, 3);
  const auto path = test::scratch_dir("gather") + "/np" + std::to_string(comm->getSize()) + ".e";
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

}  // namespace
}  // namespace efg
