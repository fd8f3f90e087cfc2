// An explicit run of 1000 steps on N ranks gives the histories of the one-rank run (computed on
// MPI_COMM_SELF in the same process) to 1e-10 relative.
#include <gtest/gtest.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <cstdio>

#include "io/ExodusReader.hpp"
#include "run/Simulation.hpp"
#include "scene/SceneReader.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

const char* kScene = R"(
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [1, 0.05], cells: [40, 2], perturbation: 0.2, seed: 2}
parts:
  - {name: bar, blocks: [block_1], material: m, plane: stress}
materials:
  - {name: m, model: linear_elastic, density: 1.0, youngs_modulus: 100.0, poissons_ratio: 0.25}
initial_conditions:
  - {type: velocity, node_set: all, value: [-1.0, 0.5]}
rigid_walls:
  - {name: wall, point: [-0.01, 0], normal: [1, 0]}
stages:
  - {name: bounce, driver: explicit, end_time: 1.0, dt: 0.001, output_interval: 0.1}
output:
  fields: [displacement, velocity]
  history_node_sets: [all]
)";

TEST(ExplicitRanks, ThousandStepsMatchOneRank) {
  if (Tpetra::getDefaultComm()->getSize() == 1)
    GTEST_SKIP() << "a one-rank run compared with itself proves nothing: needs 2 or more ranks";
  const auto world = Tpetra::getDefaultComm();
  const CommPtr self = Teuchos::rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const auto dir = test::scratch_dir("explicit_ranks");
  const auto distributed = dir + "/np" + std::to_string(world->getSize()) + ".e";
  const auto serial = dir + "/self_rank" + std::to_string(world->getRank()) + "_of" +
                      std::to_string(world->getSize()) + ".e";
  run_stages(world, build_model(world, parse_scene(kScene, "bounce.yaml")), distributed);
  run_stages(self, build_model(self, parse_scene(kScene, "bounce.yaml")), serial);
  world->barrier();
  if (world->getRank() != 0) return;
  const auto a = read_exodus_results(distributed), b = read_exodus_results(serial);
  ASSERT_EQ(a.times.size(), b.times.size());
  ASSERT_EQ(a.times.size(), 11u);  // 1000 steps of 0.001, a record every 100
  double worst = 0, scale = 0;
  for (const auto& name : {"displacement_x", "displacement_y", "velocity_x", "velocity_y"})
    for (std::size_t k = 0; k < a.times.size(); ++k)
      for (std::size_t n = 0; n < a.nodal.at(name)[k].size(); ++n) {
        worst = std::max(worst, std::abs(a.nodal.at(name)[k][n] - b.nodal.at(name)[k][n]));
        scale = std::max(scale, std::abs(b.nodal.at(name)[k][n]));
      }
  for (const auto& name : {"kinetic_energy", "internal_energy", "wall_wall_force"})
    for (std::size_t k = 0; k < a.times.size(); ++k)
      EXPECT_NEAR(a.global.at(name)[k], b.global.at(name)[k],
                  1e-10 * std::max(1.0, std::abs(b.global.at(name)[k])))
          << name;
  EXPECT_LT(worst / scale, 1e-10);
  std::printf("explicit, %d ranks vs one, 1000 steps: largest nodal difference %.3e relative\n",
              world->getSize(), worst / scale);
}

}  // namespace
}  // namespace efg
