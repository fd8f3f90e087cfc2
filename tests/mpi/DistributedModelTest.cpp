#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <cmath>

#include "contact/SurfaceFacets.hpp"
#include "io/ExodusReader.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/MeshGenerator.hpp"
#include "model/Model.hpp"
#include "operators/ModelOperators.hpp"
#include "scene/SceneReader.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// A 120 x 4 x 4 hex bar on [0, 30] x [0, 1] x [0, 1] (cells 0.25 wide: 121 planes of 25 nodes),
// written by rank 0, read by a scene with mesh.read: distributed.
const char* kScene = R"(
mesh: {file: bar.exo, read: distributed}
parts:
  - {name: bar, blocks: [block_1], material: steel, section: {dilation: 1.5, integration: scni}}
materials:
  - {name: steel, model: linear_elastic, density: 1, youngs_modulus: 100, poissons_ratio: 0.3}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0, z: 0}
loads:
  - {name: tip, type: nodal_force, node_set: xmax, value: [0, 0, -1]}
stages:
  - {name: load, driver: implicit, end_time: 1}
)";

std::string bar_scene(const CommPtr& comm) {
  const auto dir = test::scratch_dir("distributed_model_np" + std::to_string(comm->getSize()));
  if (comm->getRank() == 0) {
    GeneratorSpec bar;
    bar.upper = {30, 1, 1};
    bar.cells = {120, 4, 4};
    ExodusWriter writer(dir + "/bar.exo", generate_mesh(bar), {}, "distributed model test");
    writer.close();
  }
  comm->barrier();
  return dir + "/bar.yaml";
}

// The model of a mesh read (or generated) in slices holds about one rank's share of the mesh on
// each rank. The halo (model/DistributedMesh.hpp) for dilation 1.5 box supports on 0.25 cells, by
// hand: reach sqrt(3) x 0.375 = 0.650, halo 2 x 0.650 + sqrt(3) x 0.25 = 1.732, so at most 7
// planes beyond the owned ones, plus a partly owned plane and the far plane of the cells reaching
// into the box: 9 per cut. Bound: 121 / p + 1 planes owned + 9 per side, 25 nodes each (p = 2:
// 66 % of the mesh, p = 3: 49 %); the owned particles are those RCB gives the whole mesh.
void expect_one_ranks_share(const CommPtr& comm, const Model& model, const BackgroundMesh& whole) {
  const auto p = static_cast<double>(comm->getSize());
  const double nodes = 121 * 25;
  EXPECT_TRUE(model.mesh.is_part());
  EXPECT_TRUE(model.scene.output.per_rank_files);  // no rank could gather the whole mesh
  EXPECT_EQ(model.mesh.whole_node_count(), 121 * 25);
  EXPECT_EQ(model.mesh.whole_cell_count(), 120 * 16);
  if (comm->getSize() > 1) {
    EXPECT_LE(static_cast<double>(model.mesh.node_count()), (121 / p + 1 + 2 * 9) * 25);
    EXPECT_LE(static_cast<double>(model.mesh.cell_count()), (120 / p + 2 + 2 * 9) * 16);
  }
  double owned = static_cast<double>(model.partition.owned.size()), total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, owned, Teuchos::outArg(total));
  EXPECT_EQ(total, nodes);

  // The same owners as the whole mesh's partition (made whole here for the test only).
  const auto reference = partition_nodes(comm, whole);
  ASSERT_EQ(model.partition.owned.size(), reference.owned.size());
  for (std::size_t i = 0; i < reference.owned.size(); ++i)
    EXPECT_EQ(model.mesh.global_node(static_cast<std::size_t>(model.partition.owned[i])),
              reference.owned[i]);
}

TEST(DistributedModel, HoldsAboutOneRanksShareOfTheMeshRead) {
  const auto comm = Tpetra::getDefaultComm();
  const auto path = bar_scene(comm);
  const auto model = build_model(comm, parse_scene(kScene, path));
  expect_one_ranks_share(comm, model, read_exodus_mesh(path.substr(0, path.size() - 5) + ".exo"));
}

// The same bar generated (mesh.generate with read: distributed): every rank makes only its slice
// of the generator's nodes and cells (mesh/GeneratedSlice.hpp) and keeps the same part.
TEST(DistributedModel, HoldsAboutOneRanksShareOfTheMeshGenerated) {
  const auto comm = Tpetra::getDefaultComm();
  std::string text = kScene;
  const std::string file = "file: bar.exo, read: distributed";
  text.replace(text.find(file), file.size(),
               "generate: {element: hex8, lower: [0, 0, 0], upper: [30, 1, 1], cells: [120, 4, "
               "4]}, read: distributed");
  const auto dir = test::scratch_dir("distributed_generated_np" + std::to_string(comm->getSize()));
  const auto model = build_model(comm, parse_scene(text, dir + "/bar.yaml"));
  GeneratorSpec bar;
  bar.upper = {30, 1, 1};
  bar.cells = {120, 4, 4};
  expect_one_ranks_share(comm, model, generate_mesh(bar));
}

// support_size: per_part gives every particle of a part the part's largest half-widths over the
// whole mesh. On a bar graded along x (cells from 0.05 to 0.45 long: x = 30 s^2 for s in
// [0, 1]) the largest is at x = 30, far from the ranks owning the small cells: each rank's
// part alone would give those a smaller support. Read in slices, every owned particle has the
// supports it has when the mesh is read whole (same partition, same order), exactly.
TEST(DistributedModel, PerPartSupportsAreTheWholePartsLargest) {
  const auto comm = Tpetra::getDefaultComm();
  const auto dir = test::scratch_dir("distributed_support_np" + std::to_string(comm->getSize()));
  if (comm->getRank() == 0) {
    GeneratorSpec bar;
    bar.upper = {1, 1, 1};
    bar.cells = {60, 3, 3};
    bar.coordinate_map = [](const double* box, double* x) {
      x[0] = 30 * box[0] * box[0];
      x[1] = box[1];
      x[2] = box[2];
    };
    ExodusWriter writer(dir + "/graded.exo", generate_mesh(bar), {}, "graded bar");
    writer.close();
  }
  comm->barrier();
  std::string text = kScene;
  text.replace(text.find("bar.exo"), 7, "graded.exo");
  text.replace(text.find("dilation: 1.5"), 13, "dilation: 1.5, support_size: per_part");
  const auto distributed = build_model(comm, parse_scene(text, dir + "/graded.yaml"));
  text.replace(text.find(", read: distributed"), 19, "");
  const auto whole = build_model(comm, parse_scene(text, dir + "/graded.yaml"));
  ASSERT_TRUE(distributed.mesh.is_part());
  ASSERT_FALSE(whole.mesh.is_part());
  const auto& a = distributed.parts[0].cloud;
  const auto& b = whole.parts[0].cloud;
  ASSERT_EQ(a.owned_count, b.owned_count);
  for (std::size_t i = 0; i < a.owned_count; ++i) {
    EXPECT_EQ(distributed.mesh.global_node(static_cast<std::size_t>(a.mesh_node[i])),
              b.mesh_node[i]);
    for (std::size_t d = 0; d < 3; ++d) EXPECT_EQ(a.a(i)[d], b.a(i)[d]) << "particle " << i;
  }
  // The largest cell is 30 (1 - (59/60)^2) = 0.99 long: with dilation 1.5 no support is shorter
  // than 1.49 along x.
  EXPECT_GT(a.a(0)[0], 1.48);
}

// The contact surface of a part on a mesh read in slices is the whole mesh's on every rank: each
// rank lists the facets whose lowest node it owns (its part's own edge is no surface) and all
// gather them in the whole mesh's order. The bar's surface: 2 x 16 end quadrilaterals + 4 x 120
// x 4 side ones, 2 triangles each.
TEST(DistributedModel, ContactSurfaceIsTheWholeMeshs) {
  const auto comm = Tpetra::getDefaultComm();
  const auto path = bar_scene(comm);
  const auto sliced = build_model(comm, parse_scene(kScene, path));
  std::string text = kScene;
  text.replace(text.find(", read: distributed"), 19, "");
  const auto whole = build_model(comm, parse_scene(text, path));
  const auto a = surface_facets(sliced, {"bar"}), b = surface_facets(whole, {"bar"});
  EXPECT_EQ(b.count(), 2u * (2 * 16 + 4 * 120 * 4));
  EXPECT_EQ(a.node_id, b.node_id);
  EXPECT_EQ(a.facet, b.facet);
  EXPECT_EQ(a.reference_size, b.reference_size);
}

// Mixed u-p pressure cells on a part: every rank's cells carry the ids the whole mesh gives them
// (the whole mesh's index of the cell), so the pressure maps of the bulk split are one-to-one over
// the ranks and the same as with the mesh read whole (same partition, same owned cells).
TEST(DistributedModel, MixedPressureCellsKeepTheWholeMeshsIds) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string scene = R"(
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [6, 1], cells: [48, 8]}
  read: distributed
parts:
  - {name: block, blocks: [block_1], material: rubber, plane: strain, formulation: mixed_up}
materials:
  - {name: rubber, model: linear_elastic, youngs_modulus: 10, poissons_ratio: 0.4999}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0}
stages:
  - {name: load, driver: implicit, end_time: 1}
)";
  const auto dir = test::scratch_dir("distributed_mixed_np" + std::to_string(comm->getSize()));
  auto ids = [&](const std::string& text) {
    const auto model = build_model(comm, parse_scene(text, dir + "/mixed.yaml"));
    const ModelOperators ops(model);
    std::vector<long long> id(ops.mixed()->cell_count());
    ops.mixed()->bulk_group_ids(id.data());
    return id;
  };
  std::string whole = scene;
  whole.erase(whole.find("  read: distributed\n"), 20);
  const auto sliced = ids(scene);
  EXPECT_EQ(sliced, ids(whole));
  // One-to-one: the ids over all ranks are 0 .. 383, each once.
  const int mine = static_cast<int>(sliced.size());
  int total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(total));
  ASSERT_EQ(total, 48 * 8);
  std::vector<int> seen(static_cast<std::size_t>(total), 0), all(seen.size(), 0);
  for (auto g : sliced) ++seen[static_cast<std::size_t>(g)];
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, total, seen.data(), all.data());
  for (int count : all) EXPECT_EQ(count, 1);
}

}  // namespace
}  // namespace efg
