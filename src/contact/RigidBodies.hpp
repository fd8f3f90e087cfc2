// The scene's rigid bodies: shapes, masses and motions, and their time integration in an
// explicit stage, in the same velocity-Verlet form as the particles (drivers/ExplicitDriver):
//   free:       v^(n+1/2) = v^n + dt/2 (F^n / M + g),  u^(n+1) = u^n + dt v^(n+1/2),
//               v^(n+1) = v^(n+1/2) + dt/2 (F^(n+1) / M + g)   (F: the contact force on the
//               body, g its gravity)
//   prescribed: u^(n+1) = u^n + dt v_bar c(t + dt/2),  v^(n+1) = v_bar c(t + dt)
//   fixed:      never moves.
// Rotation: free bodies given an angular_velocity (2D discs and boxes, spheres, 3D boxes)
// integrate their angular momentum about the centre in the same form with the moment M of their
// contact forces, L += dt/2 M, and turn by the mid-step angular velocity omega = I^-1 L (the
// principal moments I in the body's axes, turned with it in 3D: contact/RigidOrientation.hpp);
// prescribed ones turn at angular_velocity x curve. Other bodies translate only.
// The scene's rigid walls (rigid_walls, LS-DYNA *RIGIDWALL_PLANAR) are fixed planes appended
// after the scene's bodies: one contact code path for walls and bodies.
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

  /// All bodies: the scene's rigid_bodies, then one fixed plane per rigid wall.
  std::size_t count() const { return bodies_.size(); }
  /// The scene's rigid_bodies (the first ones; their states are the history's).
  std::size_t scene_count() const { return scene_count_; }
  /// Index of rigid wall w.
  std::size_t wall(std::size_t w) const { return scene_count_ + w; }
  const std::string& name(std::size_t b) const { return bodies_[b].name; }
  const contact::Shape& shape(std::size_t b) const { return bodies_[b].shape; }
  bool is_free(std::size_t b) const { return bodies_[b].motion == "free"; }
  bool rotates(std::size_t b) const { return !bodies_[b].angular_velocity.empty(); }
  double mass(std::size_t b) const { return bodies_[b].mass; }

  /// States at the start of a run at `time`: initial velocity (free), v_bar c(time) (prescribed).
  std::vector<RigidBodyState> initial_states(double time) const;
  /// First half of a step from `time` over dt, with the forces of the last evaluation.
  void move(std::vector<RigidBodyState>& states, double time, double dt) const;
  /// Second half, with the forces of the new evaluation (in states[b].force).
  void finish(std::vector<RigidBodyState>& states, double time_end, double dt) const;
  /// Displacement of a prescribed body from time t0 to t1: velocity x the integral of its curve
  /// (per component with axis_curves)
  /// (exact for the piecewise-linear curves; zero for fixed and free bodies). Implicit stages.
  std::array<double, 3> prescribed_travel(std::size_t b, double t0, double t1) const;
  /// The turn of a prescribed spinning body from t0 to t1: angular_velocity x the integral of
  /// its curve (a rotation vector about a fixed axis, exact; 2D: about z). Implicit stages.
  std::array<double, 3> prescribed_turn(std::size_t b, double t0, double t1) const;
  /// Kinetic energy of the free bodies (prescribed motions are driven from outside: their
  /// energy is the work they do on the particles).
  double kinetic_energy(const std::vector<RigidBodyState>& states) const;
  /// Work of the free bodies' gravity and applied forces from the `before` states (time t0) to
  /// `after` (t1): external work (the applied force by the trapezoid rule over the step).
  double applied_work(const std::vector<RigidBodyState>& before,
                      const std::vector<RigidBodyState>& after, double t0, double t1) const;
  /// A free body's own contact frequency, omega^2 dt^2 = penalty sum m_J / M over the particles
  /// it touches (`penalty_mass` = penalty sum m_J), must stay below 1 with the particles' share
  /// (central differences need it below 4): throws NumericalError naming body b otherwise.
  /// `where` follows "its contact" in the message (e.g. " with the shell").
  void check_contact_mass(std::size_t b, double penalty_mass, const char* where = "") const;
  /// The load a free body carries in an implicit (static) stage at `time`: its applied force
  /// x curve (x `no_curve` without one: the implicit stages' ramp of loads) plus its weight,
  /// mass x gravity x `no_curve` (ramped as the parts' own body loads). Its contact forces
  /// balance it there.
  std::array<double, 3> static_load(std::size_t b, double time, double no_curve) const;
  /// The axis of that load (a unit vector; its applied force's, or its gravity's without one;
  /// zeros without either): a free body in an implicit stage moves along it only.
  std::array<double, 3> static_load_axis(std::size_t b) const;
  /// Momentum of the free bodies, per direction.
  std::array<double, 3> momentum(const std::vector<RigidBodyState>& states) const;

 private:
  struct Body {
    std::string name, motion, curve;
    std::array<std::string, 3> axis_curve;  ///< the curve of each velocity component
    std::vector<double> velocity, gravity;
    contact::Shape shape;
    double mass;
    std::vector<double> force;             // applied (free bodies), x curve
    std::vector<double> angular_velocity;  // initial; empty: does not rotate
    std::array<double, 9> inertia{};       // tensor about the centre, body axes (rotating bodies)
  };
  /// The turn of free rotating body b over a step (first half of the angular momentum's kick).
  void turn_free(std::size_t b, RigidBodyState& s, double dt) const;
  double gravity(std::size_t b, int k) const {
    const auto& g = bodies_[b].gravity;
    return static_cast<std::size_t>(k) < g.size() ? g[static_cast<std::size_t>(k)] : 0.0;
  }
  /// The applied force on free body b at `time`, component k.
  double applied_force(std::size_t b, int k, double time, double no_curve = 1.0) const;
  /// Acceleration of free body b from its contact force, gravity and applied force.
  double acceleration(std::size_t b, int k, const RigidBodyState& s, double time) const {
    return (s.force[k] + applied_force(b, k, time)) / bodies_[b].mass + gravity(b, k);
  }
  const Scene& scene_;
  int dim_;
  std::vector<Body> bodies_;
  std::size_t scene_count_ = 0;
};

}  // namespace efg
