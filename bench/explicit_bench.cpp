// Explicit step cost: wall time per particle-step and memory per particle for a 3D block of 1e4
// to 1e5 particles (linear basis, SCNI, dilation 1.2 and 1.5), beside the bytes one step must
// move (the memory-bandwidth floor). One step = one internal force evaluation (the dominant
// cost: displacement gradient and stress per point, then the per-particle gather of the
// forces) plus the velocity-Verlet vector updates.
//   efg_bench_explicit [--max-particles N]
#include <Tpetra_Core.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "ExplicitStep.hpp"
#include "operators/ModelOperators.hpp"
#include "run/RunSummary.hpp"
#include "scene/SceneReader.hpp"

int main(int argc, char** argv) {
  const long long max_particles = bench_option(argc, argv, "--max-particles", 100000);
  int library_argc = 1;
  Tpetra::ScopeGuard scope(&library_argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  std::printf("%10s %8s %12s %14s %12s %14s %12s\n", "particles", "dilation", "entries/pt",
              "ns/particle-step", "MiB/particle", "bytes/step", "GB/s moved");
  for (long long target : {10000LL, 30000LL, 100000LL}) {
    if (target > max_particles) break;
    const int n = static_cast<int>(
        std::lround(std::cbrt(static_cast<double>(target) / 4.0)));  // 4n x n x n cells
    for (double dilation : {1.2, 1.5}) {
      const long long rss_before = efg::peak_memory_bytes();
      char text[1024];
      std::snprintf(
          text, sizeof text,
          "mesh:\n  generate: {element: hex8, lower: [0, 0, 0], upper: [4, 1, 1], cells: [%d, %d, "
          "%d]}\n"
          "parts:\n  - {name: b, blocks: [block_1], material: m, section: {dilation: %g}}\n"
          "materials:\n  - {name: m, model: linear_elastic, density: 1.0, youngs_modulus: 100, "
          "poissons_ratio: 0.3}\n",
          4 * n, n, n, dilation);
      const auto model = efg::build_model(comm, efg::parse_scene(text, "bench.yaml"));
      efg::ModelOperators ops(model);
      const auto particles = static_cast<double>(model.mesh.node_count());
      const long long rss_after = efg::peak_memory_bytes();
      efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
          f(model.maps.owned_dofs);
      d.randomize(-1e-3, 1e-3);
      const int steps = 20;
      const auto start = std::chrono::steady_clock::now();
      for (int s = 0; s < steps; ++s) {
        explicit_step(ops, 1e-3, d, v, a, f);
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      double entries = 0;
      for (const auto& part : model.parts)
        entries += static_cast<double>(part.points.gradients.particles.size());
      // Per entry (the one-pass force of the Serial build): node id (4) + gradient (24) +
      // gathered displacement (24) + force read-modify-write (48); per point: weight and offsets
      // (16); per dof: the five vector updates read and write (5 x 16 x 3 per particle). The
      // threaded build's two passes also write and read each entry's force term and slot (~56).
      const double bytes = entries * 100.0 + particles * (16.0 + 240.0);
      const double per_step = seconds / steps;
      std::printf("%10.0f %8.1f %12.1f %14.1f %12.4f %14.3e %12.2f\n", particles, dilation,
                  entries / particles, 1e9 * per_step / particles,
                  static_cast<double>(rss_after - rss_before) / 1048576.0 / particles, bytes,
                  bytes / per_step / 1e9);
    }
  }
  return 0;
}
