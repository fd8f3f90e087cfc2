// Thread scaling of the three kernels that dominate a run, on a 3D block of >= 1e5 particles
// (hex8 background cells, linear basis, SCNI, box supports of dilation 1.2, linear elastic):
//   shape functions  neighbour search + MLS values and gradients at every owned particle
//   explicit step    one internal force (force-term pass + gather pass) plus the velocity-Verlet updates
//   tangent          one assembly of the stiffness matrix (begin, kernels, end with the export)
// One process configuration per run: bench/threads.sh runs it with 1 thread, 2 threads and
// 2 MPI ranks x 1 thread back to back and prints the ratios. Each time is the fastest of
// --repeats runs, the slowest rank's. Checksums (|f|, |K|_F) show every configuration computes
// the same numbers.
//   efg_bench_threads [--cells N] [--repeats R] [--threads T]
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "ExplicitStep.hpp"
#include "core/Threads.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "operators/CouplingGraph.hpp"
#include "operators/ModelOperators.hpp"
#include "parallel/ReproducibleSum.hpp"
#include "scene/SceneReader.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// The slowest rank's seconds for f(), the fastest of `repeats` runs.
template <class F>
double time_of(const Teuchos::Comm<int>& comm, int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    comm.barrier();
    const auto start = Clock::now();
    f();
    const double mine = std::chrono::duration<double>(Clock::now() - start).count();
    double slowest = 0;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(slowest));
    best = std::min(best, slowest);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  int cells = 48, repeats = 3;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--cells") == 0) cells = std::atoi(argv[i + 1]);
    if (std::strcmp(argv[i], "--repeats") == 0) repeats = std::atoi(argv[i + 1]);
  }
  efg::LibraryArguments library(argc, argv);
  Tpetra::ScopeGuard scope(library.argc(), library.argv());
  const auto comm = Tpetra::getDefaultComm();

  char text[1024];
  std::snprintf(text, sizeof text,
                "mesh:\n  generate: {element: hex8, lower: [0, 0, 0], upper: [1, 1, 1], cells: "
                "[%d, %d, %d]}\n"
                "parts:\n  - {name: b, blocks: [block_1], material: m, section: {dilation: 1.2}}\n"
                "materials:\n  - {name: m, model: linear_elastic, density: 1.0, youngs_modulus: "
                "100, poissons_ratio: 0.3}\n",
                cells, cells, cells);
  const auto model = efg::build_model(comm, efg::parse_scene(text, "bench.yaml"));
  efg::ModelOperators ops(model);
  const auto& cloud = model.parts.at(0).cloud;

  const double shape = time_of(*comm, repeats, [&] {
    const auto v =
        efg::evaluate_shape_functions(cloud, cloud.position.data(), cloud.owned_count, true);
    if (v.phi.empty()) std::abort();
  });

  efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
      f(model.maps.owned_dofs);
  {
    // A smooth displacement field, the same on any number of ranks and threads.
    auto dv = d.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < dv.extent(0); ++k) {
      const auto gid = model.maps.owned_dofs->getGlobalElement(static_cast<int>(k));
      dv(k, 0) = 1e-3 * static_cast<double>(gid % 7) / 7.0;
    }
  }
  ops.internal_force(d, f);
  const double force_norm = efg::reproducible_norm2(f);
  const int steps = 10;
  const double step = time_of(*comm, repeats,
                              [&] {
                                for (int s = 0; s < steps; ++s) {
                                  explicit_step(ops, 1e-9, d, v, a, f);
                                }
                              }) /
                      steps;

  efg::CouplingGraph couplings(model.maps.overlap_nodes->getNodeNumElements());
  ops.solid().add_point_couplings(couplings);
  efg::FEMatrix K(couplings.build(model.maps));
  efg::Vector d_overlap(model.maps.overlap_dofs);
  ops.to_overlap(d, d_overlap);
  const double tangent = time_of(*comm, repeats, [&] {
    K.beginAssembly();
    K.setAllToScalar(0.0);
    ops.solid().add_tangent(d_overlap, K);
    K.endAssembly();
  });
  // |K|_F by block sums (Tpetra's getFrobeniusNorm adds 1e8 squares in one running sum, whose
  // rounding alone differed by 1.8e-10 between 1 and 2 ranks at this size).
  const auto values = K.getLocalMatrixDevice().values;
  const double tangent_norm = std::sqrt(efg::sum_over_ranks(
      *comm,
      efg::block_sum(
          values.extent(0), KOKKOS_LAMBDA(const std::size_t k) { return values(k) * values(k); })));

  if (comm->getRank() == 0)
    std::printf(
        "ranks %d threads %d particles %zu shape_s %.6e step_s %.6e tangent_s %.6e force_norm "
        "%.17g tangent_norm %.17g\n",
        comm->getSize(), efg::threads_per_rank(), model.mesh.node_count(), shape, step, tangent,
        force_norm, tangent_norm);
  return 0;
}
