// The Jacobian of an implicit J2 shell stage (drivers/ShellStaticProblem: the points' consistent
// section tangent of FlatShellOperator::fill_tangent, the edge terms of ShellConstraints with the
// edge points' own layers, the collocation rows) is the derivative of its residual: K v against
// the central difference of r along v, in a plastic state (layers committed plastic at the
// points and the edge points, flowing further in the step evaluated), on a perturbed particle
// set with a clamped and a simply supported edge.
#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <sstream>

#include "drivers/ShellStaticProblem.hpp"
#include "run/ShellStageInputs.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;

Model j2_plate() {
  std::ostringstream s;
  s << "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [8, 4], "
       "perturbation: 0.25, seed: 3}\n"
    << "parts:\n  - {name: plate, blocks: [block_1], material: steel, shell: {thickness: 0.01, "
       "thickness_points: 5}, section: {basis: quadratic, dilation: 2.5}}\n"
    << "materials:\n  - {name: steel, model: j2_plasticity, youngs_modulus: 1000.0, "
       "poissons_ratio: 0.3, yield_stress: 0.1, hardening_modulus: 50}\n"
    << "boundary_conditions:\n"
    << "  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: 0, z: 0, rx: 0, ry: 0}\n"
    << "  - {name: support, type: displacement, node_set: xmax, z: 0}\n"
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
  auto K = problem.create_matrix();
  problem.jacobian(d, *K);
  Vector v(map), Kv(map), rp(map), rm(map);
  bending(model, op, 0.0, 1.0, v);
  K->apply(v, Kv);
  const double h = 1e-7;
  Vector dp(d, Teuchos::Copy), dm(d, Teuchos::Copy);
  dp.update(h, v, 1.0);
  dm.update(-h, v, 1.0);
  problem.residual(dp, rp);
  problem.residual(dm, rm);
  rp.update(-1.0 / (2 * h), rm, 1.0 / (2 * h));  // the central difference of r along v
  rp.update(-1.0, Kv, 1.0);
  EXPECT_LT(rp.normInf(), 1e-5 * Kv.normInf())
      << "K v vs the central difference: " << rp.normInf() << " of " << Kv.normInf();
}

}  // namespace
}  // namespace efg
