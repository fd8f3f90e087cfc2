// Explicit shell cost, side by side in one run (issue 18): the internal force of a flat shell
// (64 x 64 cells, 4,225 particles, quadratic basis, dilation 2.5; FlatShellOperator::internal_force
// plus the commit of the layers' J2 states, as each explicit step does) per particle-step, with
// an elastic section and with J2 through 5 and 12 Gauss layers (plastic at every layer), and
// the ratio to the elastic section.
//   efg_bench_shells
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "scene/SceneReader.hpp"
#include "shells/FlatShellOperator.hpp"

namespace {

double step_cost(const efg::CommPtr& comm, const std::string& material, int layers) {
  const std::string text =
      "mesh:\n  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [64, 64]}\n"
      "parts:\n  - {name: plate, blocks: [block_1], material: m, shell: {thickness: 0.01, "
      "thickness_points: " +
      std::to_string(layers) +
      "}, section: {basis: quadratic, dilation: 2.5}}\nmaterials:\n  - {name: m, density: 1.0, "
      "youngs_modulus: 1000, poissons_ratio: 0.3, " +
      material + "}\nstages:\n  - {name: s, driver: explicit, end_time: 1}\n";
  const auto model = efg::build_model(comm, efg::parse_scene(text, "bench.yaml"));
  const efg::FlatShellOperator op(model);
  efg::FlatShellOperator::Vector d(op.maps().owned_dofs), f(op.maps().owned_dofs);
  d.randomize(-1e-2, 1e-2);  // curvatures of order 1e-2 / h: every layer yields for J2
  op.internal_force(d, f);   // first touch
  op.commit_state();
  const int steps = 20;
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) {
    op.internal_force(d, f);
    op.commit_state();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return 1e9 * seconds / steps / static_cast<double>(model.mesh.node_count());
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  struct Case {
    const char* name;
    std::string material;
    int layers;
  };
  const Case cases[] = {{"elastic section (2 layers)", "model: linear_elastic", 2},
                        {"J2, 5 layers", "model: j2_plasticity, yield_stress: 1e-3", 5},
                        {"J2, 12 layers", "model: j2_plasticity, yield_stress: 1e-3", 12}};
  std::printf("| section | ns / particle-step | ratio to elastic |\n|---|---|---|\n");
  double reference = 0;
  for (const auto& c : cases) {
    // The smaller of two runs: the machine's other load only ever adds time.
    const double ns =
        std::min(step_cost(comm, c.material, c.layers), step_cost(comm, c.material, c.layers));
    if (reference == 0) reference = ns;
    std::printf("| %s | %.0f | %.2f |\n", c.name, ns, ns / reference);
  }
  return 0;
}
