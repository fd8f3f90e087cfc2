// Discretization benchmark: neighbour search time per particle from 1e4 to 1e6 particles (3D,
// and 2D), and MLS shape-function evaluations per second for 2D/3D, linear/quadratic basis,
// dilations 1.2/1.5/2.0. Ratios are measured side by side in one run.
//   efg_bench_discretization [--max-particles N]
#include <Tpetra_Core.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/Errors.hpp"
#include "discretization/ParticleCloud.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "mesh/MeshGenerator.hpp"

namespace {

using Clock = std::chrono::steady_clock;

efg::ParticleCloud cloud_for(int dim, long long target, double dilation, efg::Basis basis) {
  efg::GeneratorSpec spec;
  spec.dimension = dim;
  spec.element = dim == 2 ? efg::CellType::quad4 : efg::CellType::hex8;
  const int n = static_cast<int>(std::lround(std::pow(static_cast<double>(target), 1.0 / dim))) - 1;
  spec.cells = {n, n, n};
  spec.upper = {1, 1, 1};
  spec.perturbation = 0.1;
  const auto mesh = efg::generate_mesh(spec);
  efg::PartSpec part;
  part.blocks = {"block_1"};
  part.section.dilation = {dilation};
  part.section.basis = basis;
  return efg::make_particle_cloud(mesh, part, std::vector<int>(mesh.node_count(), 0), 0, {});
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  long long max_particles = 1000000;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--max-particles") == 0) max_particles = std::atoll(argv[i + 1]);
  int library_argc = 1;
  Tpetra::ScopeGuard scope(&library_argc, &argv);

  std::printf(
      "# neighbour search: cell list, box support, dilation 1.5, query at every particle\n");
  std::printf("%-4s %10s %14s %16s %12s %10s\n", "dim", "particles", "search_s", "us_per_particle",
              "neighbours", "vs_first");
  for (int dim : {3, 2}) {
    double first = 0;
    for (long long target = 10000; target <= max_particles; target *= 10) {
      const auto cloud = cloud_for(dim, target, 1.5, efg::Basis::linear);
      const auto start = Clock::now();
      const auto lists = efg::find_neighbors(cloud, cloud.position.data(), cloud.size());
      const double t = seconds_since(start);
      const double per = 1e6 * t / static_cast<double>(cloud.size());
      if (first == 0) first = per;
      std::printf("%-4d %10zu %14.4f %16.4f %12.2f %10.2f\n", dim, cloud.size(), t, per,
                  static_cast<double>(lists.particles.size()) / static_cast<double>(cloud.size()),
                  per / first);
    }
  }

  std::printf(
      "\n# MLS shape functions and gradients at every particle of a ~1e5-particle cloud (neighbour "
      "search excluded)\n");
  std::printf("%-4s %-10s %8s %10s %12s %14s %16s\n", "dim", "basis", "dilation", "points",
              "neighbours", "evals_per_s", "entries_per_s");
  for (int dim : {2, 3})
    for (auto basis : {efg::Basis::linear, efg::Basis::quadratic})
      for (double dilation : {1.2, 1.5, 2.0}) {
        const auto cloud = cloud_for(dim, std::min(100000LL, max_particles), dilation, basis);
        // evaluate_shape_functions includes the search; time the search alone and subtract it.
        auto start = Clock::now();
        const auto lists = efg::find_neighbors(cloud, cloud.position.data(), cloud.size());
        const double search = seconds_since(start);
        start = Clock::now();
        efg::ShapeFunctionValues v;
        try {
          v = efg::evaluate_shape_functions(cloud, cloud.position.data(), cloud.size(), true);
        } catch (const efg::NumericalError& e) {
          std::printf("%-4d %-10s %8.1f   not usable: %.60s...\n", dim,
                      basis == efg::Basis::linear ? "linear" : "quadratic", dilation,
                      e.what() + std::strlen("shape functions: "));
          continue;
        }
        const double t = seconds_since(start) - search;
        std::printf("%-4d %-10s %8.1f %10zu %12.2f %14.3e %16.3e\n", dim,
                    basis == efg::Basis::linear ? "linear" : "quadratic", dilation, cloud.size(),
                    static_cast<double>(lists.particles.size()) / static_cast<double>(cloud.size()),
                    static_cast<double>(cloud.size()) / t, static_cast<double>(v.phi.size()) / t);
      }
  return 0;
}
