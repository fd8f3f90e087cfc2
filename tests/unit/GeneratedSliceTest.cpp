// A generated mesh made in slices (mesh/GeneratedSlice.hpp) is the whole generated mesh cut into
// ranges: the slices of ranks 0..p-1 concatenated give generate_mesh's (and append_generated's)
// coordinates, cells, blocks and sets entry for entry, each set entry at its position in the
// whole set. The whole generator is checked on its own (MeshGeneratorTest: volumes tile the box,
// sides tile its faces).
#include <gtest/gtest.h>

#include "core/Errors.hpp"
#include "mesh/GeneratedSlice.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

// The whole mesh the generator makes of `main` and `more`.
BackgroundMesh whole(const GeneratorSpec& main, const std::vector<GeneratorSpec>& more) {
  auto mesh = generate_mesh(main);
  for (const auto& spec : more) append_generated(mesh, spec);
  return mesh;
}

void expect_slices_make(const BackgroundMesh& mesh, const GeneratorSpec& main,
                        const std::vector<GeneratorSpec>& more, int ranks) {
  SCOPED_TRACE(mesh.source + " in " + std::to_string(ranks) + " slices");
  std::vector<double> coordinates;
  std::vector<std::vector<GlobalIndex>> connectivity(mesh.blocks.size());
  std::vector<std::vector<GlobalIndex>> node_sets(mesh.node_sets.size());
  std::vector<std::vector<std::pair<GlobalIndex, int>>> side_sets(mesh.side_sets.size());
  for (int r = 0; r < ranks; ++r) {
    const auto slice = generate_slice(main, more, r, ranks);
    EXPECT_EQ(slice.source, mesh.source);
    EXPECT_EQ(slice.dimension, mesh.dimension);
    EXPECT_EQ(slice.node_count, static_cast<GlobalIndex>(mesh.node_count()));
    EXPECT_EQ(slice.cell_count, static_cast<GlobalIndex>(mesh.cell_count()));
    EXPECT_EQ(slice.first_node, static_cast<GlobalIndex>(coordinates.size()) / mesh.dimension);
    coordinates.insert(coordinates.end(), slice.coordinates.begin(), slice.coordinates.end());
    ASSERT_EQ(slice.blocks.size(), mesh.blocks.size());
    GlobalIndex first_cell = 0;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      const auto& block = slice.blocks[b];
      EXPECT_EQ(block.name, mesh.blocks[b].name);
      EXPECT_EQ(block.id, mesh.blocks[b].id);
      EXPECT_EQ(block.type, mesh.blocks[b].type);
      EXPECT_EQ(block.first_cell, first_cell);
      EXPECT_EQ(block.cell_count, static_cast<GlobalIndex>(mesh.blocks[b].cell_count()));
      if (block.read_count() > 0) {
        EXPECT_EQ(block.first_read,
                  first_cell + static_cast<GlobalIndex>(
                                   connectivity[b].size() /
                                   static_cast<std::size_t>(cell_node_count(block.type))));
      }
      first_cell += block.cell_count;
      connectivity[b].insert(connectivity[b].end(), block.connectivity.begin(),
                             block.connectivity.end());
    }
    ASSERT_EQ(slice.node_sets.size(), mesh.node_sets.size());
    for (std::size_t s = 0; s < mesh.node_sets.size(); ++s) {
      EXPECT_EQ(slice.node_sets[s].name, mesh.node_sets[s].name);
      EXPECT_EQ(slice.node_sets[s].id, mesh.node_sets[s].id);
      if (!slice.node_sets[s].nodes.empty()) {
        EXPECT_EQ(slice.node_sets[s].first_entry, static_cast<GlobalIndex>(node_sets[s].size()))
            << slice.node_sets[s].name << " on rank " << r;
      }
      node_sets[s].insert(node_sets[s].end(), slice.node_sets[s].nodes.begin(),
                          slice.node_sets[s].nodes.end());
    }
    ASSERT_EQ(slice.side_sets.size(), mesh.side_sets.size());
    for (std::size_t s = 0; s < mesh.side_sets.size(); ++s) {
      const auto& set = slice.side_sets[s];
      EXPECT_EQ(set.name, mesh.side_sets[s].name);
      EXPECT_EQ(set.id, mesh.side_sets[s].id);
      if (!set.cells.empty()) {
        EXPECT_EQ(set.first_entry, static_cast<GlobalIndex>(side_sets[s].size()))
            << set.name << " on rank " << r;
      }
      for (std::size_t i = 0; i < set.cells.size(); ++i)
        side_sets[s].emplace_back(set.cells[i], set.sides[i]);
    }
  }
  EXPECT_EQ(coordinates, mesh.coordinates);  // to the last bit: the same arithmetic
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    EXPECT_EQ(connectivity[b], std::vector<GlobalIndex>(mesh.blocks[b].connectivity.begin(),
                                                        mesh.blocks[b].connectivity.end()))
        << mesh.blocks[b].name;
  for (std::size_t s = 0; s < mesh.node_sets.size(); ++s)
    EXPECT_EQ(node_sets[s], std::vector<GlobalIndex>(mesh.node_sets[s].nodes.begin(),
                                                     mesh.node_sets[s].nodes.end()))
        << mesh.node_sets[s].name;
  for (std::size_t s = 0; s < mesh.side_sets.size(); ++s) {
    std::vector<std::pair<GlobalIndex, int>> expected;
    for (std::size_t i = 0; i < mesh.side_sets[s].cells.size(); ++i)
      expected.emplace_back(mesh.side_sets[s].cells[i], mesh.side_sets[s].sides[i]);
    EXPECT_EQ(side_sets[s], expected) << mesh.side_sets[s].name;
  }
}

class GeneratedSliceByElement : public ::testing::TestWithParam<CellType> {};

TEST_P(GeneratedSliceByElement, SlicesConcatenateToTheWholeMesh) {
  // Perturbed (the seeded stream taken up in the middle) and mapped (coordinates bent after the
  // cells are cut), with a second, separate body of another size, seed and block name.
  auto main = test::box_spec(GetParam(), 3, 0.3, 5);
  main.coordinate_map = [](const double* box, double* x) {
    x[0] = box[0] + 0.1 * box[1] * box[1];
    x[1] = box[1] * (1 + 0.2 * box[0]);
    x[2] = box[2] + 0.05 * box[0];
  };
  main.map_text = "(bent)";
  auto second = test::box_spec(GetParam(), 2, 0.2, 9);
  second.block_name = "second";
  second.lower = {3, 0, 0};
  second.upper = {4, 2, 1};
  for (int ranks : {1, 2, 3, 5, 7}) {
    expect_slices_make(whole(main, {}), main, {}, ranks);
    expect_slices_make(whole(main, {second}), main, {second}, ranks);
  }
  // More ranks than cells along the body: ranks with no cell of a block, or no node of a body.
  const auto tiny = test::box_spec(GetParam(), 1, 0.25, 2);
  expect_slices_make(whole(tiny, {second}), tiny, {second}, 40);
}

INSTANTIATE_TEST_SUITE_P(AllElements, GeneratedSliceByElement,
                         ::testing::Values(CellType::quad4, CellType::tri3, CellType::hex8,
                                           CellType::tet4, CellType::wedge6),
                         [](const auto& p) { return cell_scene_name(p.param); });

TEST(GeneratedSlice, RefusesWhatTheWholeGeneratorRefuses) {
  auto spec = test::box_spec(CellType::hex8, 2);
  spec.dimension = 2;
  EXPECT_THROW(generate_slice(spec, {}, 0, 2), InputError);
  const auto main = test::box_spec(CellType::hex8, 2);
  EXPECT_THROW(generate_slice(main, {main}, 1, 2), InputError);  // block name taken
  EXPECT_THROW(generate_slice(main, {test::box_spec(CellType::quad4, 2)}, 0, 2), InputError);
}

}  // namespace
}  // namespace efg
