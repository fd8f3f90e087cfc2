// The cost of loads written as expressions of time (issue 19), side by side with the explicit step
// in one run: a 3D block (linear basis, SCNI, dilation 1.5) under a body force on every
// integration point, either constant (assembled once, scaled per step) or an expression of x, y,
// z and t (evaluated at every point at every step, muParser bytecode, then spread by the stored
// rows of phi_I). Prints ns per load point per step for the load (evaluation + spread), for the
// evaluation of its expressions alone, and the load's share of the explicit step.
//   efg_bench_expressions [--cells N]   (N x N x N cells on a unit cube, default 24)
#include <Tpetra_Core.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "ExplicitStep.hpp"
#include "model/Curves.hpp"
#include "scene/SceneReader.hpp"

int main(int argc, char** argv) {
  const int cells = static_cast<int>(bench_option(argc, argv, "--cells", 24));
  int library_argc = 1;
  Tpetra::ScopeGuard scope(&library_argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  std::printf("%-10s %10s %12s %10s %13s %14s %16s %8s\n", "body force", "particles", "load points",
              "step ms", "loads ms", "ns/point", "eval ns/point", "share");
  for (const std::string value :
       {"[0, 0, -9.81]", "[\"0.1*sin(2*pi*t)*y\", 0, \"-9.81*(1 + 0.5*sin(2*pi*t)*x*z)\"]"}) {
    char text[2048];
    std::snprintf(text, sizeof text,
                  "mesh:\n  generate: {element: hex8, lower: [0, 0, 0], upper: [1, 1, 1], cells: "
                  "[%d, %d, %d]}\n"
                  "parts:\n  - {name: b, blocks: [block_1], material: m}\n"
                  "materials:\n  - {name: m, model: linear_elastic, density: 1.0, "
                  "youngs_modulus: 100, poissons_ratio: 0.3}\n"
                  "loads:\n  - {name: g, type: body_force, value: %s}\n"
                  "stages:\n  - {name: s, driver: explicit, end_time: 1}\n",
                  cells, cells, cells, value.c_str());
    const auto model = efg::build_model(comm, efg::parse_scene(text, "bench.yaml"));
    efg::ModelOperators ops(model);
    efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
        f(model.maps.owned_dofs), f_ext(model.maps.owned_dofs);
    const int steps = 20;
    auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) explicit_step(ops, 1e-3, d, v, a, f);
    const double step_seconds = seconds_since(t0) / steps;
    t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s)
      ops.loads().assemble(efg::curve_factor(model.scene, 1e-3 * s, 1.0), f_ext);
    const double load_seconds = seconds_since(t0) / steps;
    const bool timed = value.find('t') != std::string::npos;
    const auto& ip = model.parts.front().points;
    const auto points = static_cast<double>(ip.size());
    // The evaluation alone: every component of the load at every point.
    t0 = std::chrono::steady_clock::now();
    double sum = 0;
    for (int s = 0; s < steps; ++s)
      for (std::size_t q = 0; q < ip.size(); ++q) {
        const double x[3] = {ip.x[3 * q], ip.x[3 * q + 1], ip.x[3 * q + 2]};
        for (const auto& component : model.scene.loads.front().value)
          sum += component.at(x, 1e-3 * s);
      }
    const double eval_seconds = seconds_since(t0) / steps;
    if (!(sum == sum)) return 1;  // keeps the loop
    std::printf("%-10s %10zu %12.0f %10.3f %13.3f %14.1f %16.1f %7.1f%%\n",
                timed ? "f(x, t)" : "constant", model.mesh.node_count(), points, 1e3 * step_seconds,
                1e3 * load_seconds, 1e9 * load_seconds / points, 1e9 * eval_seconds / points,
                100 * load_seconds / (step_seconds + load_seconds));
  }
  return 0;
}
