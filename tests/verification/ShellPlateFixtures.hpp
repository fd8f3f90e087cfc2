// The flat unit-square plate of the shell verification tests (ShellTest, ShellWeakSupportTest):
// its scene, supports holding a field on every edge, a direct linear solve and the patch error.
#pragma once

#include <gtest/gtest.h>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "scene/SceneReader.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellConstraints.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace shell_plate {

using Field = std::function<void(const double* x, double (&d)[shell_dofs_per_node])>;

inline std::string plate_scene(double thickness, int cells, double perturbation,
                               double dilation = 2.5) {
  std::ostringstream s;
  s.precision(17);
  s << "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [" << cells << ", "
    << cells << "], perturbation: " << perturbation << ", seed: 3}\n"
    << "parts:\n  - {name: plate, blocks: [block_1], material: steel, plane: stress, thickness: "
    << thickness << ", section: {basis: quadratic, dilation: " << dilation << "}}\n"
    << "materials:\n  - {name: steel, model: linear_elastic, youngs_modulus: 1000.0, "
       "poissons_ratio: 0.3, density: 1}\n"
    << "stages:\n  - {name: load, driver: explicit, end_time: 1}\n";
  return s.str();
}

/// Every edge of the unit square holds all five components at the values of `field`.
inline std::vector<ShellSupport> all_edges(const Field& field,
                                           ShellMethod method = ShellMethod::transformation,
                                           double alpha = 0) {
  std::vector<ShellSupport> supports;
  for (const char* set : {"xmin", "xmax", "ymin", "ymax"}) {
    ShellSupport s;
    s.node_set = set;
    s.method = method;
    s.alpha = alpha;
    for (int c = 0; c < shell_dofs_per_node; ++c)
      s.value[static_cast<std::size_t>(c)] = [field, c](const double* x) {
        double d[shell_dofs_per_node];
        field(x, d);
        return d[c];
      };
    supports.push_back(s);
  }
  return supports;
}

struct Solution {
  std::vector<double> d, physical;  ///< generalized and physical values, 5 per owned particle
  std::vector<double> resultants;   ///< N, M, Q: 8 per owned particle
  double strain_energy = 0;         ///< this rank's
  std::vector<double> x;            ///< particle positions, 2 per owned particle
};

inline Solution solve(const Model& model, const std::vector<ShellSupport>& supports,
                      double pressure) {
  FlatShellOperator op(model);
  ShellConstraints constraints(model, op, supports);
  const auto K = op.stiffness(constraints);
  FlatShellOperator::Vector f(op.maps().owned_dofs), d(op.maps().owned_dofs);
  op.add_pressure([pressure](std::size_t, const double*) { return pressure; }, f);
  constraints.set_values(f);
  const auto lu = make_direct_preconditioner(Teuchos::ParameterList());
  lu->set_map(op.maps().owned_dofs);
  lu->compute(K);
  lu->apply(f, d, Teuchos::NO_TRANS, 1.0, 0.0);
  Solution s;
  const auto v = d.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < v.extent(0); ++i) s.d.push_back(v(i, 0));
  s.physical = op.physical_values(d);
  s.resultants = op.resultants(d);
  s.strain_energy = op.strain_energy(d);
  for (auto gid : op.maps().owned_nodes->getNodeElementList()) {
    const double* x = model.mesh.coordinates.data() + 2 * static_cast<std::size_t>(gid);
    s.x.insert(s.x.end(), {x[0], x[1]});
  }
  return s;
}

/// Largest |d_I - field(X_I)| over generalized and physical values, relative to the field's
/// largest value: an MLS basis that contains the field reproduces it with d_I = field(X_I).
inline double patch_error(const Solution& s, const Field& field) {
  double err = 0, size = 0;
  for (std::size_t i = 0; i < s.x.size() / 2; ++i) {
    double exact[shell_dofs_per_node];
    field(&s.x[2 * i], exact);
    for (std::size_t c = 0; c < shell_dofs_per_node; ++c) {
      size = std::max(size, std::abs(exact[c]));
      err = std::max({err, std::abs(s.d[i * shell_dofs_per_node + c] - exact[c]),
                      std::abs(s.physical[i * shell_dofs_per_node + c] - exact[c])});
    }
  }
  return err / size;
}

/// The owned particle nearest the centre of the unit square (one rank).
inline std::size_t centre_particle(const Solution& s) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < s.x.size() / 2; ++i)
    if (std::hypot(s.x[2 * i] - 0.5, s.x[2 * i + 1] - 0.5) <
        std::hypot(s.x[2 * best] - 0.5, s.x[2 * best + 1] - 0.5))
      best = i;
  return best;
}
inline double centre_deflection(const Solution& s) {
  return s.physical[centre_particle(s) * shell_dofs_per_node + shell_w];
}

/// Hard simple supports on every edge of the unit square: u, v, w and the rotation about the
/// edge's normal held at 0 (theta_x on x = const, theta_y on y = const).
inline std::vector<ShellSupport> hard_simple_supports(ShellMethod method) {
  const auto zero = [](const double*) { return 0.0; };
  std::vector<ShellSupport> supports;
  for (const char* set : {"xmin", "xmax", "ymin", "ymax"}) {
    ShellSupport s;
    s.node_set = set;
    s.method = method;
    s.value[shell_u] = s.value[shell_v] = s.value[shell_w] = zero;
    s.value[set[0] == 'x' ? shell_rx : shell_ry] = zero;
    supports.push_back(s);
  }
  return supports;
}

/// The thin (t/a = 1e-3) simply supported plate under unit pressure on 16 x 16 and 32 x 32
/// cells against Navier's series, w_c = 0.00406235 q a^4 / D (Timoshenko & Woinowsky-Krieger
/// 1959, sec. 30, table 8): within 0.4 % and 0.12 %, the error falling at least 2.5x.
inline void expect_navier(const std::vector<ShellSupport>& supports, const std::string& label) {
  const auto comm = Tpetra::getDefaultComm();
  const double E = 1000.0, nu = 0.3, q = 1.0, t = 0.001;
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  double previous = 1;
  for (int cells : {16, 32}) {
    const auto model = build_model(comm, parse_scene(plate_scene(t, cells, 0.0), "ss.yaml"));
    const double w = centre_deflection(solve(model, supports, q)) / (q / D);
    const double error = std::abs(w / 0.00406235 - 1);
    ::testing::Test::RecordProperty(label + std::to_string(cells),
                                    (std::ostringstream() << w).str());
    EXPECT_LT(error, cells == 16 ? 0.004 : 0.0012) << cells << " cells";
    EXPECT_LT(error, previous / 2.5) << cells << " cells";
    previous = error;
  }
}

}  // namespace shell_plate
}  // namespace efg
