#include <gtest/gtest.h>

#include <cmath>

#include "core/Errors.hpp"
#include "mesh/MeshValidation.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

std::string error_of(const BackgroundMesh& mesh) {
  try {
    validate_mesh(mesh);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshValidation, NodeIndexOutOfRange) {
  auto mesh = generate_mesh(test::box_spec(CellType::hex8, 2));
  mesh.blocks[0].connectivity[5] = static_cast<LocalIndex>(mesh.node_count() + 3);
  EXPECT_NE(error_of(mesh).find("cell 1 refers to node"), std::string::npos) << error_of(mesh);
}

TEST(MeshValidation, InvertedCell) {
  auto mesh = generate_mesh(test::box_spec(CellType::quad4, 2));
  auto& c = mesh.blocks[0].connectivity;
  std::swap(c[1], c[3]);  // clockwise quad
  EXPECT_NE(error_of(mesh).find("cell 1 is inverted"), std::string::npos) << error_of(mesh);
}

TEST(MeshValidation, ZeroVolumeCell) {
  auto mesh = generate_mesh(test::box_spec(CellType::tet4, 1));
  auto& c = mesh.blocks[0].connectivity;
  c[3] = c[2];  // two equal nodes: a flat tet
  EXPECT_NE(error_of(mesh).find("degenerate"), std::string::npos) << error_of(mesh);
}

TEST(MeshValidation, SetIndicesOutOfRange) {
  auto mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.node_sets[0].nodes.push_back(-1);
  EXPECT_NE(error_of(mesh).find("node set 'xmin' refers to node 0"), std::string::npos)
      << error_of(mesh);
  mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.side_sets[0].sides[0] = 6;
  EXPECT_NE(error_of(mesh).find("names side 7 of a hex8 cell"), std::string::npos)
      << error_of(mesh);
  mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.side_sets[0].cells[0] = 99;
  EXPECT_NE(error_of(mesh).find("refers to cell 100"), std::string::npos) << error_of(mesh);
}

TEST(MeshValidation, NonFiniteCoordinate) {
  auto mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.coordinates[4] = std::nan("");
  EXPECT_NE(error_of(mesh).find("non-finite"), std::string::npos);
}

TEST(MeshValidation, GeneratedMeshesAreValid) {
  for (auto t : {CellType::quad4, CellType::tri3, CellType::hex8, CellType::tet4, CellType::wedge6})
    EXPECT_EQ(error_of(generate_mesh(test::box_spec(t, 3, 0.3))), "");
}

// Issue 14, item 9: scenes name sets and blocks, so duplicates are ambiguous input.
TEST(MeshValidation, DuplicateSetNames) {
  auto mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.node_sets[1].name = mesh.node_sets[0].name;
  EXPECT_NE(error_of(mesh).find("has two node sets named 'xmin'"), std::string::npos)
      << error_of(mesh);
  mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.side_sets[2].name = mesh.side_sets[0].name;
  EXPECT_NE(error_of(mesh).find("has two side sets named"), std::string::npos) << error_of(mesh);
  mesh = generate_mesh(test::box_spec(CellType::hex8, 1));
  mesh.blocks.push_back(mesh.blocks[0]);
  mesh.blocks.back().id = 2;
  EXPECT_NE(error_of(mesh).find("has two element blocks named 'block_1'"), std::string::npos)
      << error_of(mesh);
}

}  // namespace
}  // namespace efg
