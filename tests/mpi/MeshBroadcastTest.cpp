#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "core/Errors.hpp"
#include "parallel/MeshBroadcast.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

TEST(MeshBroadcast, EveryRankReceivesRankZerosMesh) {
  const auto comm = Tpetra::getDefaultComm();
  const auto expected = generate_mesh(test::box_spec(CellType::wedge6, 3, 0.2));
  int calls = 0;
  const auto mesh = load_on_root_and_broadcast(comm, [&] {
    ++calls;
    return expected;
  });
  EXPECT_EQ(calls, comm->getRank() == 0 ? 1 : 0);  // loaded once, on rank 0
  EXPECT_EQ(mesh.coordinates, expected.coordinates);
  EXPECT_EQ(mesh.blocks[0].connectivity, expected.blocks[0].connectivity);
  EXPECT_EQ(mesh.side_sets.back().sides, expected.side_sets.back().sides);
  EXPECT_EQ(mesh.node_sets.back().name, expected.node_sets.back().name);
  EXPECT_EQ(mesh.source, expected.source);
}

TEST(MeshBroadcast, AnInputErrorOnRankZeroIsRaisedOnEveryRank) {
  const auto comm = Tpetra::getDefaultComm();
  try {
    load_on_root_and_broadcast(
        comm, []() -> BackgroundMesh { throw InputError("mesh file 'x.e': broken"); });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "mesh file 'x.e': broken");
  }
}

TEST(MeshBroadcast, SerializationRoundTrip) {
  const auto mesh = generate_mesh(test::box_spec(CellType::tet4, 2));
  const auto copy = deserialize(serialize(mesh));
  EXPECT_EQ(copy.coordinates, mesh.coordinates);
  EXPECT_EQ(copy.blocks[0].type, mesh.blocks[0].type);
  EXPECT_EQ(copy.side_sets.size(), mesh.side_sets.size());
}

}  // namespace
}  // namespace efg
