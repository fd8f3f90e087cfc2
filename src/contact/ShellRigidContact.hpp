// Penalty contact of flat shells with rigid bodies in explicit stages (a sheet pressed by a
// punch, dropped on a die): every particle of a named shell part is a candidate, on both faces.
// Its mid-surface point x_J = X_J + sum_I phi_I(X_J) u_I (the translations; X_J in the plane
// z = 0) is tested against the body's shape at the body's current place; the sheet's face on the
// body's side is half the thickness nearer, so the gap is g = g_mid - t_J / 2 and, inside
// (g < 0), the particle gets the force of the solids' explicit contact (contact/PenaltyContact):
//   F = max(0, k (-g) - c v_n) n,  k = penalty m_J / dt^2,  c = 2 damping sqrt(k m_J),
// n the body's outward normal at the nearest point, m_J the particle's translational lumped mass,
// v_n its approach speed over the last step; with friction the Coulomb return map of the solids'
// contact (contact/CoulombFriction.hpp: regularized stick of stiffness k, mu_s / mu_d with the
// decay law) on the particle's slip against the body's surface over the step adds the tangential
// force; f_I += phi_I(X_J) F on the translations, -F on the body. The moment of the force about the mid-surface (the offset t / 2 n) is
// left out: for a thin sheet it is t / 2 |F|, small against the bending moments it causes. The
// stable step is reduced by sqrt(1 - (penalty + 2 damping) / 4), as for rigid walls.
// Bodies: fixed, prescribed (a driven tool) or free (a ball dropped on a plate: moved by the
// contact force, its gravity and applied force in the velocity-Verlet form of RigidBodies);
// their force on the sheet is its external work.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/CoulombFriction.hpp"
#include "contact/RigidBodies.hpp"
#include "shells/FlatShellOperator.hpp"

namespace efg {

class ShellRigidContact {
 public:
  using Vector = FlatShellOperator::Vector;

  /// The contacts of the scene active in `stage` (rigid_body contacts of shell parts).
  ShellRigidContact(const Model& model, const FlatShellOperator& op, const Vector& mass_owned,
                    const std::string& stage);
  /// A contact acts in `stage`.
  static bool wanted(const Scene& scene, const std::string& stage);

  /// The bodies' places and velocities at `time` (the stage start; bodies start where the scene
  /// puts them plus their travel before it); `dt` the stage's step, which the penalty is scaled
  /// to (a shorter last step keeps it: k = penalty m / dt_step^2 would blow up there).
  void start(double time, double dt);
  /// Moves the bodies over the step from `time` to `time + dt` (free bodies: the first half
  /// kick with the last forces) ...
  void move(double time, double dt);
  /// ... and completes the step at `time_end` with the new forces (free bodies' second kick).
  void finish(double time_end, double dt);
  /// Per scene rigid body its velocity (3 components).
  std::vector<double> body_velocities() const;
  /// f_owned = the contact forces on the sheet at d (owned, overwritten), `step` the step that
  /// led to d (the approach speed); the bodies' forces (summed over ranks, collective) kept for
  /// body_forces().
  void forces(const Vector& d_owned, double step, Vector& f_owned);
  /// Adds the last forces' impulse over a step (the mean force over a record interval).
  void accumulate(double step);
  /// Per scene rigid body the mean contact force on it since the previous call (3 components),
  /// over `elapsed`; with elapsed 0 the last forces(). Resets the impulse.
  std::vector<double> mean_body_forces(double elapsed);
  /// The largest penalty + 2 damping of the contacts (the stable step's reduction).
  double stability_share() const { return share_; }

 private:
  struct Candidate {
    std::array<double, 3> X{};
    std::vector<int> nodes;  ///< overlap particles reaching X
    std::vector<double> phi;
    double mass = 0, half_thickness = 0;
    std::array<double, 3> x_old{}, ft{};  ///< last position, tangential force
    bool started = false;
  };
  struct Pair {
    std::size_t body = 0;
    double penalty = 0.1, damping = 0;
    contact::Friction friction;
    std::array<double, 3> body_u_old{}, body_rotation_old{};  ///< the body at the last forces()
    std::vector<Candidate> candidates;
  };
  const Model& model_;
  const FlatShellOperator& op_;
  RigidBodies bodies_;
  std::vector<RigidBodyState> states_;
  std::vector<Pair> pairs_;
  double share_ = 0;
  double dt_ = 1;                ///< the stage's step (the penalty's scale)
  std::vector<double> impulse_;  ///< per scene body, 3 components, since the last mean
};

}  // namespace efg
