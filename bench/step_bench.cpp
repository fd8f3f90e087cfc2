// The kernel's explicit step on a scene's own model, for bench/driver_step.sh to set beside the
// whole driver (`efg run`) on the same scene: one internal force plus the velocity-Verlet updates
// (bench/ExplicitStep.hpp, as efg_bench_threads and efg_bench_explicit time it; unit mass, no
// loads), from the displacement field of efg_bench_threads. Prints the particles, the steps and
// the seconds per step (the fastest of --repeats runs of --steps steps, after one warm-up step).
//   efg_bench_step --scene FILE [--steps N] [--repeats R]
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "ExplicitStep.hpp"
#include "model/Model.hpp"
#include "operators/ModelOperators.hpp"

int main(int argc, char** argv) {
  std::string scene;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--scene") == 0) scene = argv[i + 1];
  if (scene.empty()) {
    std::fprintf(stderr, "usage: efg_bench_step --scene FILE [--steps N] [--repeats R]\n");
    return 2;
  }
  const auto steps = bench_option(argc, argv, "--steps", 100);
  const auto repeats = bench_option(argc, argv, "--repeats", 3);
  int library_argc = 1;
  Tpetra::ScopeGuard guard(&library_argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const auto model = efg::build_model(comm, scene);
  efg::ModelOperators ops(model);
  efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
      f(model.maps.owned_dofs);
  {
    auto dv = d.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < dv.extent(0); ++k) {
      const auto gid = model.maps.owned_dofs->getGlobalElement(static_cast<int>(k));
      dv(k, 0) = 1e-3 * static_cast<double>(gid % 7) / 7.0;
    }
  }
  explicit_step(ops, 1e-9, d, v, a, f);  // warm-up: first touch of the work vectors
  double best = 1e300;
  for (long long r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    for (long long s = 0; s < steps; ++s) explicit_step(ops, 1e-9, d, v, a, f);
    best = std::min(best, seconds_since(start) / static_cast<double>(steps));
  }
  if (comm->getRank() == 0)
    std::printf("particles %lld steps %lld step_s %.6e\n",
                static_cast<long long>(model.mesh.whole_node_count()), steps, best);
  return 0;
}
