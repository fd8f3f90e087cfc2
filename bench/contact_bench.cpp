// Contact cost beside the explicit step, measured side by side in one run: a 3D block (linear
// basis, SCNI, dilation 1.5) whose whole top face is pressed by a rigid plane (every top particle
// in contact, with Coulomb friction), then by a rigid sphere (a patch in contact), then by a
// second deformable block of the same size laid on it, overlapping by 1e-3 (contact between
// deformable parts, two-way: gathering both surfaces, bins, facet search, reactions), then by a
// rigid body of mesh cells over the same face (`shape: mesh`, N/2 x N/2 x 1 hex8: the facet
// search in the body's frame against the analytic plane's O(1)). Per step:
// the internal force with the velocity-Verlet updates (bench/ExplicitStep.hpp) and the contact
// forces with their friction commit (contact/PenaltyContact, contact/SurfaceContact). Prints ns
// per candidate (surface particle) and per active contact particle, and the contact's share of
// the step.
//   efg_bench_contact [--cells N]   (N x N x N/4 cells on a 4 x 4 x 1 block, default 40)
#include <Tpetra_Core.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>

#include "ExplicitStep.hpp"
#include "contact/PenaltyContact.hpp"
#include "contact/SurfaceContact.hpp"
#include "operators/LumpedMass.hpp"
#include "scene/SceneReader.hpp"

namespace {

// One contact under test: its forces at d (with the commit), its candidate and active counts.
struct ContactUnderTest {
  std::function<void(const efg::Vector& d_overlap, efg::Vector& f_overlap)> evaluate;
  std::function<long long()> candidates, active;
};

std::string scene_text(int cells, const std::string& extra) {
  char text[2048];
  std::snprintf(text, sizeof text,
                "mesh:\n  generate: {element: hex8, lower: [0, 0, 0], upper: [4, 4, 1], cells: "
                "[%d, %d, %d]}\n%s"
                "materials:\n  - {name: m, model: linear_elastic, density: 1.0, "
                "youngs_modulus: 100, poissons_ratio: 0.3}\n"
                "stages:\n  - {name: s, driver: explicit, end_time: 1}\n",
                cells, cells, cells / 4, extra.c_str());
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const int cells = static_cast<int>(bench_option(argc, argv, "--cells", 40));
  int library_argc = 1;
  Tpetra::ScopeGuard scope(&library_argc, &argv);
  const auto comm = Tpetra::getDefaultComm();
  std::printf("%-8s %10s %11s %8s %13s %13s %14s %14s %8s\n", "tool", "particles", "candidates",
              "active", "step ms", "contact ms", "ns/candidate", "ns/active", "share");
  const std::string one_part =
      "parts:\n  - {name: b, blocks: [block_1], material: m, section: {dilation: 1.5}}\n";
  const std::string friction = "static_friction: 0.3, dynamic_friction: 0.2";
  char second[512];
  std::snprintf(second, sizeof second,
                "  more_blocks:\n    - {element: hex8, lower: [0, 0, 0.999], upper: [4, 4, 1.999], "
                "cells: [%d, %d, %d], block_name: top}\n",
                cells, cells, cells / 4);
  char die[512];
  std::snprintf(die, sizeof die,
                "  more_blocks:\n    - {element: hex8, lower: [0, 0, 0.999], upper: [4, 4, 1.999], "
                "cells: [%d, %d, 1], block_name: die}\n",
                cells / 2, cells / 2);
  const struct {
    const char* name;
    std::string extra;
  } cases[] = {
      {"plane", one_part +
                    "rigid_bodies:\n  - {name: tool, shape: plane, point: [0, 0, 0.999], "
                    "normal: [0, 0, -1]}\ncontacts:\n  - {name: press, rigid_body: tool, "
                    "parts: [b], " +
                    friction + "}\n"},
      {"sphere", one_part +
                     "rigid_bodies:\n  - {name: tool, shape: sphere, center: [2, 2, 2.9], "
                     "radius: 1.91}\ncontacts:\n  - {name: press, rigid_body: tool, parts: "
                     "[b], " +
                     friction + "}\n"},
      {"mesh", std::string(die) + one_part +
                   "rigid_bodies:\n  - {name: tool, shape: mesh, blocks: [die]}\ncontacts:\n"
                   "  - {name: press, rigid_body: tool, parts: [b], " +
                   friction + "}\n"},
      {"block", std::string(second) + one_part +
                    "  - {name: t, blocks: [top], material: m, section: {dilation: 1.5}}\n"
                    "contacts:\n  - {name: press, parts: [t], target_parts: [b], " +
                    friction + "}\n"},
  };
  for (const auto& c : cases) {
    const auto model =
        efg::build_model(comm, efg::parse_scene(scene_text(cells, c.extra), "b.yaml"));
    efg::ModelOperators ops(model);
    const auto mass = efg::lumped_mass(ops);
    efg::RigidBodies bodies(model.scene, 3);
    auto states = bodies.initial_states(0.0);
    efg::Vector d(model.maps.owned_dofs), v(model.maps.owned_dofs), a(model.maps.owned_dofs),
        f(model.maps.owned_dofs), d_overlap(model.maps.overlap_dofs),
        f_overlap(model.maps.overlap_dofs);
    ops.to_overlap(d, d_overlap);
    efg::PenaltyContact rigid(ops, mass, bodies, "");
    efg::SurfaceContact surfaces(ops, mass, "");
    ContactUnderTest contact;
    if (std::string(c.name) == "block") {
      surfaces.start(d_overlap);
      contact = {[&](const efg::Vector& x, efg::Vector& y) {
                   surfaces.add_forces(x, 1e-3, y);
                   surfaces.commit();
                 },
                 [&] { return surfaces.candidate_count(); },
                 [&] { return surfaces.active_count(); }};
    } else {
      rigid.start(d_overlap, states, false);
      contact = {[&](const efg::Vector& x, efg::Vector& y) {
                   rigid.add_forces(x, 1e-3, 0.0, states, y);
                   rigid.commit(states);
                 },
                 [&] { return rigid.candidate_count(); }, [&] { return rigid.active_count(); }};
    }
    const int steps = 20;
    auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) explicit_step(ops, 1e-3, d, v, a, f);
    const double step_seconds = seconds_since(t0) / steps;
    d.putScalar(0.0);  // the tools' overlap as laid out
    ops.to_overlap(d, d_overlap);
    t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
      f_overlap.putScalar(0.0);
      contact.evaluate(d_overlap, f_overlap);
    }
    const double contact_seconds = seconds_since(t0) / steps;
    const auto candidates = static_cast<double>(contact.candidates());
    const auto active = contact.active();
    std::printf("%-8s %10zu %11.0f %8lld %13.3f %13.3f %14.1f %14.1f %7.1f%%\n", c.name,
                model.mesh.node_count(), candidates, active, 1e3 * step_seconds,
                1e3 * contact_seconds, 1e9 * contact_seconds / candidates,
                active > 0 ? 1e9 * contact_seconds / static_cast<double>(active) : 0.0,
                100 * contact_seconds / (step_seconds + contact_seconds));
  }
  return 0;
}
