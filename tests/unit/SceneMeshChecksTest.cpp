// Checks between a scene and its mesh that need the mesh's contents (issue 14, items 9 and 12):
// an empty node set under a load, parts that share nodes. Each message names the scene file,
// line, column and key.
#include <gtest/gtest.h>

#include <string>

#include "core/Errors.hpp"
#include "mesh/MeshGenerator.hpp"
#include "scene/SceneMeshChecks.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

std::string error_of(const Scene& scene, const BackgroundMesh& mesh) {
  try {
    check_scene_against_mesh(scene, mesh);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

BackgroundMesh strip(const Scene& scene) {
  return generate_mesh(*scene.generator);
}

TEST(SceneMeshChecks, NodalForceOnAnEmptySet) {
  const auto scene = parse_scene(R"(mesh:
  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [2, 1]}
parts:
  - {name: p, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.25}
loads:
  - {name: f, type: nodal_force, node_set: xmax, value: [1, 0]}
)",
                                 "empty.yaml");
  auto mesh = strip(scene);
  EXPECT_EQ(error_of(scene, mesh), "");
  for (auto& s : mesh.node_sets)
    if (s.name == "xmax") s.nodes.clear();
  EXPECT_EQ(error_of(scene, mesh),
            "empty.yaml:8:44: loads[0].node_set: node set 'xmax' is empty; expected a set with "
            "nodes");
}

TEST(SceneMeshChecks, PartsSharingNodesAreNamedWhereTheSecondPartTakesTheBlock) {
  const auto scene = parse_scene(R"(mesh:
  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [2, 1]}
parts:
  - {name: soft, blocks: [block_1], material: m}
  - {name: hard, blocks: [block_2], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.25}
)",
                                 "bonded.yaml");
  // Two cells side by side, one per block: they share the two nodes of the middle edge.
  auto mesh = strip(scene);
  auto second = mesh.blocks[0];
  second.name = "block_2";
  second.id = 2;
  const auto per = static_cast<std::size_t>(cell_node_count(second.type));
  second.connectivity.assign(mesh.blocks[0].connectivity.begin() + static_cast<long>(per),
                             mesh.blocks[0].connectivity.end());
  mesh.blocks[0].connectivity.resize(per);
  mesh.blocks.push_back(second);
  const auto error = error_of(scene, mesh);
  EXPECT_NE(error.find("bonded.yaml:5:27: parts[1].blocks[0]: part 'hard' shares mesh node "),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("with part 'soft'"), std::string::npos) << error;
}

}  // namespace
}  // namespace efg
