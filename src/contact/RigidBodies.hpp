// The scene's rigid bodies: shapes, masses and motions, and their time integration in an
// explicit stage, in the same velocity-Verlet form as the particles (drivers/ExplicitDriver):
//   free:       v^(n+1/2) = v^n + dt/2 F^n / M,  u^(n+1) = u^n + dt v^(n+1/2),
//               v^(n+1) = v^(n+1/2) + dt/2 F^(n+1) / M   (F: the contact force on the body)
//   prescribed: u^(n+1) = u^n + dt v_bar c(t + dt/2),  v^(n+1) = v_bar c(t + dt)
//   fixed:      never moves.
// Translation only: a body does not rotate (its friction moment is not integrated yet).
#pragma once

#include <string>
#include <vector>

#include "contact/RigidBodyState.hpp"
#include "contact/RigidShape.hpp"
#include "scene/Scene.hpp"

namespace efg {

class RigidBodies {
 public:
  RigidBodies(const Scene& scene, int dim);

  std::size_t count() const { return bodies_.size(); }
  const std::string& name(std::size_t b) const { return bodies_[b].spec->name; }
  const contact::Shape& shape(std::size_t b) const { return bodies_[b].shape; }
  bool is_free(std::size_t b) const { return bodies_[b].spec->motion == "free"; }
  double mass(std::size_t b) const { return bodies_[b].mass; }

  /// States at the start of a run at `time`: initial velocity (free), v_bar c(time) (prescribed).
  std::vector<RigidBodyState> initial_states(double time) const;
  /// First half of a step from `time` over dt, with the forces of the last evaluation.
  void move(std::vector<RigidBodyState>& states, double time, double dt) const;
  /// Second half, with the forces of the new evaluation (in states[b].force).
  void finish(std::vector<RigidBodyState>& states, double dt) const;
  /// Kinetic energy of the free bodies (prescribed motions are driven from outside: their
  /// energy is the work they do on the particles).
  double kinetic_energy(const std::vector<RigidBodyState>& states) const;
  /// Momentum of the free bodies, per direction.
  std::array<double, 3> momentum(const std::vector<RigidBodyState>& states) const;

 private:
  struct Body {
    const RigidBodySpec* spec;
    contact::Shape shape;
    double mass;
  };
  const Scene& scene_;
  int dim_;
  std::vector<Body> bodies_;
};

}  // namespace efg
