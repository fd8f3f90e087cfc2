// The Jacobian of an implicit J2 shell stage (drivers/ShellStaticProblem: the points' consistent
// section tangent of FlatShellOperator::fill_tangent, the edge terms of ShellConstraints with the
// edge points' own layers, the collocation rows) is the derivative of its residual: K v against
// the central difference of r along v, in a plastic state (layers committed plastic at the
// points and the edge points, flowing further in the step evaluated), on a perturbed particle
// set with a clamped and a simply supported edge.
#include <gtest/gtest.h>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "drivers/ShellStaticProblem.hpp"
#include "run/ShellStageInputs.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;

Model j2_plate(bool finite_rotations = false, bool elastic = false,
               const std::string& method = "transformation") {
  std::ostringstream s;
  s << "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [8, 4], "
       "perturbation: 0.25, seed: 3}\n"
    << "parts:\n  - {name: plate, blocks: [block_1], material: steel, shell: {thickness: 0.01, "
       "thickness_points: 5}, section: {basis: quadratic, dilation: 2.5"
    << (finite_rotations ? ", formulation: total_lagrangian" : "") << "}}\n"
    << "materials:\n  - {name: steel, model: "
    << (elastic ? "linear_elastic" : "j2_plasticity, yield_stress: 0.1, hardening_modulus: 50")
    << ", youngs_modulus: 1000.0, poissons_ratio: 0.3}\n"
    << "boundary_conditions:\n"
    << "  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0, z: 0, rx: 0, ry: 0, "
       "method: "
    << method << "}\n"
    << "  - {name: support, type: displacement, node_set: xmax, z: 0.01, method: " << method
    << "}\n"
    << "stages:\n  - {name: press, driver: implicit, end_time: 1}\n";
  return build_model(Tpetra::getDefaultComm(), parse_scene(s.str(), "shell_tangent.yaml"));
}

// Generalized dofs of a bending state w = c x^2, theta_y = 2 c x (curvature 2 c, Kirchhoff-like)
// with a smooth perturbation of every dof (membrane, twist and shear present).
void bending(const Model& model, const FlatShellOperator& op, double c, double wobble, Vector& d) {
  auto v = d.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto& nodes = *op.maps().owned_nodes;
  for (std::size_t i = 0; i < nodes.getNodeNumElements(); ++i) {
    const auto node = static_cast<std::size_t>(nodes.getGlobalElement(static_cast<int>(i)));
    const double x = model.mesh.coordinates[2 * node], y = model.mesh.coordinates[2 * node + 1];
    for (std::size_t k = 0; k < nd; ++k)
      v(i * nd + k, 0) = wobble * std::sin(1.3 * x + 0.7 * y + 0.9 * static_cast<double>(k));
    v(i * nd + shell_w, 0) += c * x * x;
    v(i * nd + shell_ry, 0) += 2 * c * x;
  }
}

// K v against the central difference of r along v (a wobble of every dof) at d, step h, each
// dof kind bounded on its own (the membrane rows are (L/t)^2 larger than the bending ones: one
// bound for all would not see an error in the rotation rows).
void expect_jacobian_is_derivative(const Model& model, const FlatShellOperator& op,
                                   ShellStaticProblem& problem, const Vector& d, double h,
                                   double tolerance) {
  const auto& map = op.maps().owned_dofs;
  auto K = problem.create_matrix();
  problem.jacobian(d, *K);
  Vector v(map), Kv(map), rp(map), rm(map);
  bending(model, op, 0.0, 1.0, v);
  K->apply(v, Kv);
  Vector dp(d, Teuchos::Copy), dm(d, Teuchos::Copy);
  dp.update(h, v, 1.0);
  dm.update(-h, v, 1.0);
  problem.residual(dp, rp);
  problem.residual(dm, rm);
  rp.update(-1.0 / (2 * h), rm, 1.0 / (2 * h));  // the central difference of r along v
  rp.update(-1.0, Kv, 1.0);
  const auto error = rp.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto scale = Kv.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t c = 0; c < nd; ++c) {
    double e = 0, s = 0;
    for (std::size_t i = c; i < error.extent(0); i += nd) {
      e = std::max(e, std::abs(error(i, 0)));
      s = std::max(s, std::abs(scale(i, 0)));
    }
    double all[2], local[2] = {e, s};
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_MAX, 2, local, all);
    EXPECT_LT(all[0], tolerance * all[1])
        << "K v vs the central difference, dof " << c << ": " << all[0] << " of " << all[1];
  }
}

// Nitsche and penalty supports (shells/ShellWeakEdges.cpp; the second prescribes w = 0.01, so
// the terms in g are there too): the residual of an elastic plate is affine in d, and the
// Jacobian its exact derivative.
TEST(ShellTangent, JacobianWithNitscheAndPenaltySupportsIsTheDerivative) {
  for (const char* method : {"nitsche", "penalty"}) {
    const auto model = j2_plate(false, true, method);
    const FlatShellOperator op(model);
    ShellStaticProblem problem(model, op, shell_supports_at(model.scene, "press", 1.0));
    problem.set_level([](std::size_t, const double*) { return 0.0; },
                      shell_supports_at(model.scene, "press", 1.0));
    Vector d(op.maps().owned_dofs);
    bending(model, op, 0.05, 2e-3, d);
    SCOPED_TRACE(method);
    expect_jacobian_is_derivative(model, op, problem, d, 1e-4, 1e-8);
  }
}

TEST(ShellTangent, JacobianIsTheDerivativeOfTheResidualInAPlasticState) {
  const auto model = j2_plate();
  const FlatShellOperator op(model);
  ShellStaticProblem problem(model, op, shell_supports_at(model.scene, "press", 1.0));
  problem.set_level([](std::size_t, const double*) { return 0.0; },
                    shell_supports_at(model.scene, "press", 1.0));
  const auto& map = op.maps().owned_dofs;
  // An accepted plastic step: curvature 0.1, five times the yield curvature 2 sigma_y / (E t).
  Vector d(map), r(map);
  bending(model, op, 0.05, 2e-3, d);
  problem.commit(d);
  const auto plastic = op.plastic_strain();
  double largest = 0;
  for (double e : plastic) largest = std::max(largest, e);
  double all = 0;
  Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_MAX, largest, Teuchos::outArg(all));
  ASSERT_GT(all, 1e-3) << "the committed state must be plastic";
  // The step evaluated: further bending (the layers keep flowing) and another wobble.
  bending(model, op, 0.08, 3e-3, d);
  expect_jacobian_is_derivative(model, op, problem, d, 1e-7, 1e-5);
}

// Finite rotations (shells/FiniteRotation.hpp): the Jacobian of the elastic and of the J2 plate
// after an accepted step of large rotations (frames turned up to 1 radian, rotation dofs reset)
// and in a further step (rotation increments up to 0.4), membrane, bending, shear, geometric and
// edge terms all present.
// With `follower` a follower pressure (x-dependent) loads the plate: its load stiffness too.
void finite_rotation_tangent_check(bool elastic, bool follower = false) {
  const auto model = j2_plate(true, elastic);
  const FlatShellOperator op(model);
  ASSERT_TRUE(op.finite_rotations());
  ShellStaticProblem problem(model, op, shell_supports_at(model.scene, "press", 1.0));
  const FlatShellOperator::Pressure none,
      pressure = [](std::size_t, const double*x) { return 0.3 + 0.2 * x[0] * x[1]; };
  problem.set_level([](std::size_t, const double*) { return 0.0; },
                    shell_supports_at(model.scene, "press", 1.0), {}, follower ? pressure : none);
  const auto& map = op.maps().owned_dofs;
  Vector d(map), r(map);
  bending(model, op, 0.25, 2e-2, d);
  problem.commit(d);  // the frames take the rotations, the rotation dofs become 0
  EXPECT_EQ(d.getVector(0)->getLocalViewHost(Tpetra::Access::ReadOnly)(shell_ry, 0), 0.0);
  Vector step(map);
  bending(model, op, 0.1, 3e-2, step);
  d.update(1.0, step, 1.0);
  expect_jacobian_is_derivative(model, op, problem, d, 1e-6, 1e-6);
}

TEST(ShellTangent, FiniteRotationJacobianIsTheDerivativeOfTheResidualElastic) {
  finite_rotation_tangent_check(true);
}

TEST(ShellTangent, FiniteRotationJacobianIsTheDerivativeOfTheResidualPlastic) {
  finite_rotation_tangent_check(false);
}

TEST(ShellTangent, FiniteRotationJacobianHasTheFollowerPressuresLoadStiffness) {
  finite_rotation_tangent_check(true, true);
}

}  // namespace
}  // namespace efg
