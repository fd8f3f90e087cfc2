// Material cost, side by side in one run (issue 15, item 4):
//  1. the explicit step of a 3D block (about 10,000 particles, SCNI, dilation 1.5) per
//     particle-step with each law: linear elastic, neo-Hookean, J2 small strain, J2 finite
//     strain (plastic flow at every point; the history committed every step, as the explicit
//     driver does), and the ratio to linear elastic;
//  2. the dispatch an elastic part pays: physics::stress called directly against the solid
//     kernels' point_stress (one branch on the law) for the same displacement gradients.
//   efg_bench_materials
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ExplicitStep.hpp"
#include "materials/ElasticConstants.hpp"
#include "operators/ModelOperators.hpp"
#include "operators/PointMaterial.hpp"
#include "scene/SceneReader.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// ns per particle-step of explicit steps with the given material line and formulation.
double step_cost(const efg::CommPtr& comm, const std::string& material,
                 const std::string& formulation, double amplitude) {
  const int n = 14;  // 56 x 14 x 14 cells: 12,615 particles
  const std::string text =
      "mesh:\n  generate: {element: hex8, lower: [0, 0, 0], upper: [4, 1, 1], cells: [" +
      std::to_string(4 * n) + ", " + std::to_string(n) + ", " + std::to_string(n) +
      "]}\nparts:\n  - {name: b, blocks: [block_1], material: m, section: {dilation: 1.5, "
      "formulation: " +
      formulation + "}}\nmaterials:\n  - {name: m, density: 1.0, " + material + "}\n";
  const auto model = efg::build_model(comm, efg::parse_scene(text, "bench.yaml"));
  efg::ModelOperators ops(model);
  efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
      f(model.maps.owned_dofs);
  d.randomize(-amplitude, amplitude);  // strains of order amplitude x cells: plastic for J2
  auto& history = ops.solid().history();
  explicit_step(ops, 1e-6, d, v, a, f);  // first touch of the scratch and history memory
  history.commit();
  const int steps = 10;
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) {
    explicit_step(ops, 1e-6, d, v, a, f);
    history.commit();
  }
  return 1e9 * seconds_since(start) / steps / static_cast<double>(model.mesh.node_count());
}

double dispatch_cost(bool through_point_material) {
  const auto c = efg::physics::elastic_constants(100.0, 0.3);
  efg::PointMaterial m;
  m.elastic = {efg::physics::MaterialKind::linear_elastic, c.lambda, c.mu, false};
  const int count = 2000000;
  double sum = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int q = 0; q < count; ++q) {
    const double e = 1e-3 * (q % 97);
    const double H[3][3] = {{e, 0.1 * e, 0}, {0, -0.3 * e, 0}, {0.2 * e, 0, -0.3 * e}};
    double P[3][3];
    if (through_point_material)
      efg::point_stress<3>(m, q, H, P);
    else
      efg::physics::stress<3>(m.elastic, H, P);
    sum += P[0][0];
  }
  const double ns = 1e9 * seconds_since(start) / count;
  if (sum == 42.0) std::printf(" ");  // keep the loop
  return ns;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  const std::string elastic = "youngs_modulus: 100, poissons_ratio: 0.3";
  struct Case {
    const char* name;
    std::string material, formulation;
  };
  const std::vector<Case> cases = {
      {"linear elastic", "model: linear_elastic, " + elastic, "small_strain"},
      {"neo-Hookean", "model: neo_hookean, " + elastic, "total_lagrangian"},
      {"J2 small strain", "model: j2_plasticity, yield_stress: 1e-3, " + elastic, "small_strain"},
      {"J2 finite strain", "model: j2_plasticity, yield_stress: 1e-3, " + elastic,
       "total_lagrangian"}};
  std::printf("| law | ns / particle-step | ratio to linear elastic |\n|---|---|---|\n");
  double reference = 0;
  for (const auto& c : cases) {
    // The smaller of two runs: the machine's other load only ever adds time.
    const double ns = std::min(step_cost(comm, c.material, c.formulation, 1e-3),
                               step_cost(comm, c.material, c.formulation, 1e-3));
    if (reference == 0) reference = ns;
    std::printf("| %s | %.0f | %.2f |\n", c.name, ns, ns / reference);
  }
  const double direct = dispatch_cost(false), dispatched = dispatch_cost(true);
  std::printf("\nelastic stress per point: physics::stress %.2f ns, point_stress %.2f ns (%.3fx)\n",
              direct, dispatched, dispatched / direct);
  return 0;
}
