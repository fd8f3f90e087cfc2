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

// Parts of an implicit stage must be held against rigid-body motion (issue 12): the rigid modes
// restricted to the constrained dofs need full rank. Rollers on two edges hold a plate; a block
// resting on z = 0 (z fixed only) can still slide in x and y and spin about z.
TEST(SceneMeshChecks, ImplicitPartsMustBeHeldAgainstRigidMotion) {
  const char* plate = R"(mesh:
  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [4, 2]}
parts:
  - {name: p, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.25}
boundary_conditions:
  - {name: roller_x, type: displacement, node_set: xmin, x: 0}
  - {name: roller_y, type: displacement, node_set: ymin, y: 0}
stages:
  - {name: load, driver: implicit, end_time: 1}
)";
  const auto held = parse_scene(plate, "rollers.yaml");
  EXPECT_EQ(error_of(held, strip(held)), "");
  const auto block = parse_scene(R"(mesh:
  generate: {element: hex8, lower: [0, 0, 0], upper: [2, 1, 1], cells: [2, 1, 1]}
parts:
  - {name: b, blocks: [block_1], material: m}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.25}
boundary_conditions:
  - {name: floor, type: displacement, node_set: zmin, z: 0}
stages:
  - {name: load, driver: implicit, end_time: 1}
)",
                                 "floor.yaml");
  const auto error = error_of(block, strip(block));
  EXPECT_NE(error.find("floor.yaml:10:26: stages[0].driver: an implicit (static) stage needs part "
                       "'b' held against rigid-body motion"),
            std::string::npos)
      << error;
}

}  // namespace
}  // namespace efg
