// Explicit flat shells (src/shells, run/ShellExplicitStage): the lumped mass and its rotary
// inertia against hand values, the matrix-free internal force against the assembled stiffness,
// and the forward-increment Lagrange multipliers as the mass-orthogonal projection onto the
// supports. The plate's vibration period and energy balance are checked from a scene
// (cli.shell_plate_vibration).
#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "parallel/ReproducibleSum.hpp"
#include "run/Simulation.hpp"
#include "scene/SceneReader.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellMultipliers.hpp"

namespace efg {
namespace {

using Vector = FlatShellOperator::Vector;
constexpr int nd = shell_dofs_per_node;

Model plate(int cells, double perturbation, double thickness) {
  std::ostringstream s;
  s << "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [2, 1], cells: [" << 2 * cells
    << ", " << cells << "], perturbation: " << perturbation << ", seed: 5}\n"
    << "parts:\n  - {name: plate, blocks: [block_1], material: steel, shell: {thickness: "
    << thickness << "}, section: {basis: quadratic, dilation: 2.5}}\n"
    << "materials:\n  - {name: steel, model: linear_elastic, youngs_modulus: 1000.0, "
       "poissons_ratio: 0.3, density: 7.5}\n"
    << "stages:\n  - {name: shake, driver: explicit, end_time: 1}\n";
  return build_model(Tpetra::getDefaultComm(), parse_scene(s.str(), "shell_dynamics.yaml"));
}

// Every dof of every owned particle, a smooth but not polynomial field (all modes present).
void fill(Vector& x, double phase) {
  auto v = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto& map = *x.getMap();
  for (std::size_t k = 0; k < v.extent(0); ++k)
    v(k, 0) =
        std::sin(phase + 0.37 * static_cast<double>(map.getGlobalElement(static_cast<int>(k))));
}

// Row sums of the consistent mass over the nodal quadrature: the total is rho t area exactly
// (the shape functions sum to one), on a perturbed set too; the rotations carry the particle's
// mass times max(t, h)^2 / 12, h the cell size the supports were built from (regular grid).
TEST(ShellDynamics, LumpedMassIsExactAndRotaryInertiaScaled) {
  for (const auto& [thickness, perturbation] : {std::pair{0.01, 0.3}, {0.01, 0.0}, {0.5, 0.0}}) {
    const auto model = plate(6, perturbation, thickness);
    const FlatShellOperator op(model);
    const auto m = op.lumped_mass();
    const auto v = m.getLocalViewHost(Tpetra::Access::ReadOnly);
    double total[3] = {0, 0, 0}, all[3] = {0, 0, 0}, worst = 0;
    const double h = 1.0 / 6, factor = std::pow(std::max(thickness, h), 2) / 12;
    for (std::size_t i = 0; i < v.extent(0) / nd; ++i) {
      for (std::size_t c = 0; c < 3; ++c) total[c] += v(i * nd + c, 0);
      for (std::size_t c = shell_rx; c < nd; ++c)
        worst = std::max(worst, std::abs(v(i * nd + c, 0) / (v(i * nd, 0) * factor) - 1));
    }
    Teuchos::reduceAll(*m.getMap()->getComm(), Teuchos::REDUCE_SUM, 3, total, all);
    for (double t : all) EXPECT_NEAR(t, 7.5 * thickness * 2.0, 1e-12 * 15 * thickness);
    if (perturbation == 0) {
      EXPECT_LT(worst, 1e-12) << "thickness " << thickness;
    }
  }
}

// f(d) point by point equals K d of the assembled stiffness (no supports), any d.
TEST(ShellDynamics, InternalForceIsTheStiffnessTimesD) {
  const auto model = plate(5, 0.25, 0.05);
  const FlatShellOperator op(model);
  const ShellConstraints none(model, op, {});
  const auto K = op.stiffness(none);
  Vector d(op.maps().owned_dofs), Kd(op.maps().owned_dofs), f(op.maps().owned_dofs);
  fill(d, 0.3);
  K->apply(d, Kd);
  op.internal_force(d, f);
  const double size = Kd.normInf();
  f.update(-1.0, Kd, 1.0);
  EXPECT_LT(f.normInf(), 1e-12 * size);
  // and d . f = 2 x strain energy
  double e = op.strain_energy(d), energy = 0;
  Teuchos::reduceAll(*d.getMap()->getComm(), Teuchos::REDUCE_SUM, 1, &e, &energy);
  EXPECT_NEAR(reproducible_dot(d, Kd), 2 * energy, 1e-11 * energy);
}

// The corrected prediction keeps the supports (physical values 0 on the held edges) and differs
// from the prediction by a vector M-orthogonal to every motion the supports allow: the closest
// admissible state in the kinetic-energy norm (Carpenter, Taylor & Katona 1991).
TEST(ShellDynamics, MultipliersProjectOntoTheSupportsInTheMassNorm) {
  const auto model = plate(5, 0.25, 0.05);
  const FlatShellOperator op(model);
  std::vector<ShellSupport> supports;
  const auto zero = [](const double*) { return 0.0; };
  for (const char* set : {"xmin", "ymax"}) {  // a clamped edge and a simply supported one
    ShellSupport s;
    s.node_set = set;
    for (int c = 0; c < nd; ++c)
      if (set[0] == 'x' || c == shell_w || c == shell_ry)
        s.value[static_cast<std::size_t>(c)] = zero;
    supports.push_back(s);
  }
  const ShellConstraints constraints(model, op, supports);
  const auto mass = op.lumped_mass();
  const ShellMultipliers multipliers(constraints, mass);
  EXPECT_GT(multipliers.count(), 0);
  Vector predicted(mass.getMap()), d(mass.getMap()), allowed(mass.getMap());
  fill(predicted, 0.1);
  Tpetra::deep_copy(d, predicted);
  Vector force(mass.getMap());
  multipliers.correct(d, 0.5, &force);
  fill(allowed, 1.7);
  multipliers.correct(allowed, 1.0);
  // C d = 0: the physical values of the held components on the held edges
  const auto values = op.physical_values(d);
  const auto& nodes = *op.maps().owned_nodes;
  double held = 0;
  for (std::size_t i = 0; i < values.size() / nd; ++i) {
    const double* x =
        model.mesh.coordinates.data() + 2 * nodes.getGlobalElement(static_cast<int>(i));
    const bool on_x0 = x[0]<1e-12, on_y1 = x[1]> 1 - 1e-12;
    for (int c = 0; c < nd; ++c)
      if (on_x0 || (on_y1 && (c == shell_w || c == shell_ry)))
        held = std::max(held, std::abs(values[i * nd + static_cast<std::size_t>(c)]));
  }
  EXPECT_LT(held, 1e-12);
  // (d - predicted)^T M allowed = 0
  Vector change(mass.getMap()), m_allowed(mass.getMap());
  change.update(1.0, d, -1.0, predicted, 0.0);
  m_allowed.elementWiseMultiply(1.0, mass, allowed, 0.0);
  const double scale =
      std::sqrt(reproducible_dot(change, change) * reproducible_dot(m_allowed, m_allowed));
  EXPECT_LT(std::abs(reproducible_dot(change, m_allowed)), 1e-12 * scale);
  // the constraint force is M (d - predicted) / dt^2
  Vector expected(mass.getMap());
  expected.elementWiseMultiply(1.0 / 0.25, mass, change, 0.0);
  force.update(-1.0, expected, 1.0);
  EXPECT_LT(force.normInf(), 1e-12 * expected.normInf());
}

// A scene builds only what it needs: an explicit solid run constructs no shell operator, a shell
// run does (so the count can tell).
TEST(ShellDynamics, SolidSceneBuildsNoShellMachinery) {
  const auto comm = Tpetra::getDefaultComm();
  const auto dir = std::filesystem::path(EFG_TEST_TMP) / "shell_machinery";
  std::filesystem::create_directories(dir);
  const std::string solid =
      "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [4, 4]}\n"
      "parts:\n  - {name: b, blocks: [block_1], material: m}\n"
      "materials:\n  - {name: m, model: linear_elastic, youngs_modulus: 1000, "
      "poissons_ratio: 0.3, density: 1}\n"
      "stages:\n  - {name: s, driver: explicit, end_time: 1e-3}\n";
  const auto before = FlatShellOperator::instances();
  run_stages(comm, build_model(comm, parse_scene(solid, "solid.yaml")), (dir / "solid.e").string());
  EXPECT_EQ(FlatShellOperator::instances(), before);
  const auto model = plate(3, 0.0, 0.05);
  run_stages(comm, model, (dir / "shell.e").string());
  EXPECT_GT(FlatShellOperator::instances(), before);
}

}  // namespace
}  // namespace efg
