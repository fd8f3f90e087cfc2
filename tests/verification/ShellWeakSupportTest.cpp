// Nitsche and penalty supports of flat shells (shells/ShellWeakEdges.cpp): Nitsche is consistent,
// so the membrane and bending patch tests hold to round-off with every edge held weakly;
// penalty is not, and its patch error falls with alpha; the Nitsche tangent is symmetric;
// the clamped and the simply supported plate under pressure converge to Kirchhoff's series
// values as with the transformation method (ShellTest).
#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <random>
#include <sstream>

#include "ShellPlateFixtures.hpp"

namespace efg {
namespace {
using namespace shell_plate;

const Field membrane = [](const double* x, double (&d)[shell_dofs_per_node]) {
  d[shell_u] = 1e-3 * (1 + 2 * x[0] - 3 * x[1]);
  d[shell_v] = 1e-3 * (-0.5 + 1.5 * x[0] + 0.7 * x[1]);
  d[shell_w] = d[shell_rx] = d[shell_ry] = 0;
};
// Constant curvature (ShellTest's bending patch): w quadratic, theta its gradient.
const Field bending = [](const double* x, double (&d)[shell_dofs_per_node]) {
  const double a = 2e-3, b = -1e-3, c = 3e-3;
  d[shell_u] = d[shell_v] = 0;
  d[shell_w] = 1e-3 + 2e-3 * x[0] - 1e-3 * x[1] + 0.5 * a * x[0] * x[0] + b * x[0] * x[1] +
               0.5 * c * x[1] * x[1];
  d[shell_ry] = -(2e-3 + a * x[0] + b * x[1]);
  d[shell_rx] = -1e-3 + b * x[0] + c * x[1];
};

TEST(ShellWeakSupport, NitschePatchTestsOnPerturbedParticles) {
  const auto comm = Tpetra::getDefaultComm();
  for (double t : {0.1, 0.01, 0.001}) {
    const auto model = build_model(comm, parse_scene(plate_scene(t, 6, 0.3), "nitsche.yaml"));
    for (const auto* field : {&membrane, &bending}) {
      const double err =
          patch_error(solve(model, all_edges(*field, ShellMethod::nitsche), 0.0), *field);
      RecordProperty((field == &membrane ? "membrane_t" : "bending_t") + std::to_string(t),
                     (std::ostringstream() << err).str());
      // round-off grows with the ratio of shear to bending stiffness, (L / t)^2
      EXPECT_LT(err, t >= 0.01 ? 1e-10 : 1e-9)
          << (field == &membrane ? "membrane" : "bending") << ", t = " << t;
    }
  }
}

// Penalty lacks the edge traction term: the discrete solution differs from the patch field by
// the reactions' work over beta. The error falls with alpha, but more slowly than 1 / alpha
// (measured: membrane 2.2e-3 / 1.3e-4 / 3.7e-6 at alpha 1e3 / 1e5 / 1e7): the edge points hold
// combinations of many particles, and the modes that nearly satisfy them are held with a
// fraction of beta. Bounds: visible at 1e3 (not consistent), at least 10x per 100x of alpha.
TEST(ShellWeakSupport, PenaltyPatchErrorFallsWithAlpha) {
  const auto comm = Tpetra::getDefaultComm();
  const auto model = build_model(comm, parse_scene(plate_scene(0.01, 6, 0.3), "penalty.yaml"));
  for (const auto* field : {&membrane, &bending}) {
    const std::string name = field == &membrane ? "membrane" : "bending";
    double previous = 0;
    for (double alpha : {1e3, 1e5, 1e7}) {
      const double err =
          patch_error(solve(model, all_edges(*field, ShellMethod::penalty, alpha), 0.0), *field);
      RecordProperty(name + "_alpha" + std::to_string(alpha), (std::ostringstream() << err).str());
      if (previous == 0) {
        EXPECT_GT(err, 1e-4) << name;  // not consistent: a visible error
      } else {
        EXPECT_LT(err, previous / 10) << name << ", alpha " << alpha;
      }
      previous = err;
    }
  }
}

// y . K x = x . K y for the Nitsche tangent (the symmetric term is the traction term's
// transpose): the stable-step estimate of explicit stages and CG rely on it.
TEST(ShellWeakSupport, NitscheTangentIsSymmetric) {
  const auto comm = Tpetra::getDefaultComm();
  const auto model = build_model(comm, parse_scene(plate_scene(0.01, 5, 0.3), "symmetric.yaml"));
  const FlatShellOperator op(model);
  const ShellConstraints constraints(model, op, all_edges(bending, ShellMethod::nitsche));
  const auto K = op.stiffness(constraints);
  FlatShellOperator::Vector x(op.maps().owned_dofs), y(op.maps().owned_dofs),
      Kx(op.maps().owned_dofs), Ky(op.maps().owned_dofs);
  x.randomize();
  y.randomize();
  K->apply(x, Kx);
  K->apply(y, Ky);
  const double yKx = y.dot(Kx), xKy = x.dot(Ky);
  const double scale = std::sqrt(Kx.dot(Kx)) * std::sqrt(y.dot(y));
  RecordProperty("asymmetry", (std::ostringstream() << std::abs(yKx - xKy) / scale).str());
  EXPECT_LT(std::abs(yKx - xKy), 1e-13 * scale);
}

// The clamped plate (Kirchhoff w_c = 0.00126532 q a^4 / D) and the hard simply supported plate
// (Navier 0.00406235 q a^4 / D) at t/a = 1e-3 with every edge held by nitsche, and the clamped
// one by penalty (alpha 1e4, its O(1 / alpha) error far below the discretization's): the
// transformation method's bounds of ShellTest (12 x 12 within 1.5 %, 24 x 24 within 0.25 %, the
// error falling at least like h^2; simply supported 16 x 16 0.4 %, 32 x 32 0.12 %).
TEST(ShellWeakSupport, PlatesUnderPressureMatchKirchhoff) {
  const auto comm = Tpetra::getDefaultComm();
  const double E = 1000.0, nu = 0.3, q = 1.0, t = 0.001;
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  const auto clamped = [](const double*, double(&d)[shell_dofs_per_node]) {
    for (auto& v : d) v = 0;
  };
  for (auto method : {ShellMethod::nitsche, ShellMethod::penalty}) {
    const std::string name = method == ShellMethod::nitsche ? "nitsche" : "penalty";
    double previous = 1;
    for (int cells : {12, 24}) {
      const auto model = build_model(comm, parse_scene(plate_scene(t, cells, 0.0), "plate.yaml"));
      const double w = centre_deflection(solve(model, all_edges(clamped, method), q)) / (q / D);
      const double error = std::abs(w / 0.00126532 - 1);
      RecordProperty("clamped_" + name + "_" + std::to_string(cells),
                     (std::ostringstream() << w).str());
      EXPECT_LT(error, cells == 12 ? 0.015 : 0.0025) << name << ", " << cells << " cells";
      EXPECT_LT(error, previous / 4) << name << ", " << cells << " cells";
      previous = error;
    }
  }
  expect_navier(hard_simple_supports(ShellMethod::nitsche), "simply_supported_");
}

}  // namespace
}  // namespace efg
