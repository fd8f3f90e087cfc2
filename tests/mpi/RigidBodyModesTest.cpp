// The near-null space handed to multigrid: every rigid-body mode built from particle coordinates
// (solvers/RigidBodyModes) is annihilated by the unconstrained stiffness, K z = 0 to round-off,
// on perturbed particle layouts in 2D and 3D, on any rank count. This is what linear
// consistency of the shape functions promises (sum_I phi_I (a + W X_I) = a + W x).
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include "drivers/StaticProblem.hpp"
#include "scene/SceneReader.hpp"
#include "solvers/RigidBodyModes.hpp"

namespace efg {
namespace {

void expect_null_space(const std::string& mesh, int modes) {
  const std::string text = "mesh:\n  generate: " + mesh + R"(
parts:
  - {name: body, blocks: [block_1], material: m, section: {dilation: 2.0}}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 200.0, poissons_ratio: 0.3}
)";
  const Model model = build_model(Tpetra::getDefaultComm(), parse_scene(text, "free.yaml"));
  StaticProblem problem(model);  // no essential condition: K is the bare stiffness
  Vector d(model.maps.owned_dofs);
  auto K = problem.create_matrix();
  problem.jacobian(d, *K);
  const int dim = model.mesh.dimension;
  const auto z = rigid_body_modes(model.maps, model.mesh);
  ASSERT_EQ(static_cast<int>(z->getNumVectors()), modes);
  Tpetra::MultiVector<> kz(model.maps.owned_dofs, z->getNumVectors());
  K->apply(*z, kz);
  const double k_norm = K->getFrobeniusNorm();
  for (std::size_t m = 0; m < z->getNumVectors(); ++m) {
    const double z_norm = z->getVector(m)->normInf(), kz_norm = kz.getVector(m)->normInf();
    EXPECT_GT(z_norm, 0.0);
    EXPECT_LT(kz_norm, 1e-12 * k_norm * z_norm) << "mode " << m << " of " << modes;
  }
  // A field that is not rigid (a stretch u = (x, 0, 0)) is not annihilated: the test can fail.
  Vector stretch(model.maps.owned_dofs), k_stretch(model.maps.owned_dofs);
  {
    auto v = stretch.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto nodes = model.maps.owned_nodes->getNodeElementList();
    for (std::size_t i = 0; i < static_cast<std::size_t>(nodes.size()); ++i)
      v(i * static_cast<std::size_t>(dim), 0) =
          model.mesh
              .coordinates[static_cast<std::size_t>(nodes[i]) * static_cast<std::size_t>(dim)];
  }
  K->apply(stretch, k_stretch);
  EXPECT_GT(k_stretch.normInf(), 1e-6 * k_norm * stretch.normInf());
}

TEST(RigidBodyModes, AnnihilatedByTheStiffness2D) {
  expect_null_space(
      "{element: quad4, lower: [0, 0], upper: [3, 1], cells: [12, 4], perturbation: 0.25, seed: 5}",
      3);
}

TEST(RigidBodyModes, AnnihilatedByTheStiffness3D) {
  expect_null_space(
      "{element: hex8, lower: [0, 0, 0], upper: [2, 1, 1], cells: [6, 3, 3], perturbation: 0.2, "
      "seed: 7}",
      6);
}

}  // namespace
}  // namespace efg
