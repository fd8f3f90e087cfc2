// Rigid bodies, rigid walls and contacts as one explicit-stage component (built only when the
// scene has any of them): the bodies' velocity-Verlet halves around the particles' force
// evaluation, the contact forces (with rigid bodies: PenaltyContact; between deformable parts:
// SurfaceContact, built only when the scene has such a contact), the bodies' share of the
// energy account, and the state kept for a failed step. The driver sees forces on particles
// like the rigid walls' (their work is in wall_work) and body states for the history.
#pragma once

#include <memory>
#include <vector>

#include "contact/PenaltyContact.hpp"
#include "contact/RigidBodies.hpp"
#include "contact/SurfaceContact.hpp"

namespace efg {

class RigidContact {
 public:
  /// The contacts active in `stage` (bodies and walls in every stage).
  RigidContact(const ModelOperators& ops, const Vector& mass_owned, const std::string& stage);
  static bool wanted(const Scene& scene) {
    return !scene.rigid_bodies.empty() || !scene.contacts.empty() || !scene.rigid_walls.empty();
  }

  /// Stage start at `time`: the states carried over from an earlier stage, or the initial ones
  /// (then particles inside a body stop the run or have their depth ignored, per contact); a
  /// later stage takes the depths still ignored at the end of the earlier one (`allowances`:
  /// PenaltyContact::allowances, empty at the start).
  void begin(const std::vector<RigidBodyState>& carried,
             const std::vector<std::vector<double>>& allowances, double time,
             const Vector& d_overlap);
  /// Per scene contact, its particles' ignored initial depths now (to carry into a later stage).
  std::vector<std::vector<double>> allowances() const { return contact_.allowances(); }
  /// First half of a step: the bodies move to t + dt.
  void move(double time, double dt);
  /// Contact forces at d into f_overlap (the bodies' forces are kept). Collective.
  void add_forces(const Vector& d_overlap, double dt, Vector& f_overlap);
  /// Second half of a step: the free bodies' velocities. The work over the step on the free
  /// bodies: of the contact forces (trapezoidal, as the particles' wall work) and of gravity
  /// and applied forces (external work, `gravity`).
  struct Work {
    double contact = 0, gravity = 0;
  };
  Work finish(double dt);
  /// The step is accepted (friction reference, previous state for a later failure).
  void commit();
  /// Back to the state before the last move (a failed step).
  void restore();

  /// The material rule's largest k / m and its contact's damping (ContactStiffness.hpp).
  double material_frequency2() const { return contact_.material_frequency2(); }
  double material_damping() const { return contact_.material_damping(); }
  /// y += K_c x of the material rule's springs (overlap vectors; PenaltyContact).
  void add_spring_stiffness(const Vector& x_overlap, Vector& y_overlap) const {
    contact_.add_spring_stiffness(x_overlap, y_overlap);
  }
  /// Per scene contact, then per rigid wall: the deepest particle over its spacing since the last
  /// call, over the stage.
  std::vector<double> take_penetrations() { return contact_.take_penetrations(); }
  std::vector<double> stage_penetrations() const { return contact_.stage_penetrations(); }

  const std::vector<RigidBodyState>& states() const { return states_; }
  const RigidBodies& bodies() const { return bodies_; }
  double kinetic_energy() const { return bodies_.kinetic_energy(states_); }
  long long active_count() const {
    return contact_.active_count() + (surfaces_ ? surfaces_->active_count() : 0);
  }
  /// The normal force on each rigid wall at the last add_forces, then the force of each contact
  /// between deformable parts on its target parts (3 components each).
  std::vector<double> wall_forces() const;

 private:
  RigidBodies bodies_;
  PenaltyContact contact_;
  std::unique_ptr<SurfaceContact> surfaces_;
  std::vector<RigidBodyState> states_, previous_;
  double step_start_ = 0.0;  // time of the step under way (applied forces of free bodies)
  double step_end_ = 0.0;    // the time the forces are evaluated at (messages)
};

}  // namespace efg
