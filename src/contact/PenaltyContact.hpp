// Penalty contact of the surface particles of deformable parts with rigid bodies, with Coulomb
// friction, for explicit stages (LS-DYNA's node-to-rigid-surface penalty contact in meshfree
// form); the planar rigid walls are the same contact, frictionless, on every particle of their
// node set. A candidate is an owned particle J on the boundary of a named part; its physical
// position is x_J = X_J + sum_I phi_I(X_J) d_I (shape functions do not interpolate). When x_J is
// inside the body (gap g < 0 along the outward normal n):
//   normal force    F_n = max(0, k (-g) - c v_n) n,   k = penalty x m_J / dt^2 (m_J the lumped
//                   mass), c = 2 damping sqrt(k m_J) a viscous damping on the normal approach
//                   speed v_n over the last step (never pulling); the stable step is reduced by
//                   sqrt(1 - (penalty + 4 damping sqrt(penalty)) / 4) (scene/ContactInput.hpp);
//   friction        the elastic-slip return map of contact/CoulombFriction.hpp on the slip
//                   increment of the particle relative to the body over the step.
// The force F = F_n + F_t acts on the particle through its shape-function row (ParticleRow)
// and -F on the body: the
// momentum of particles plus free bodies is conserved to round-off. The friction state is
// committed when the step is accepted. Search: with analytic bodies, every candidate is tested
// each step, O(1) per particle (contact between deformable parts will need bins).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/CoulombFriction.hpp"
#include "contact/ParticleRow.hpp"
#include "contact/RigidBodies.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

class PenaltyContact {
 public:
  PenaltyContact(const ModelOperators& ops, const Vector& mass_owned, const RigidBodies& bodies,
                 const std::string& stage);

  /// The largest share of the scene's contacts in the stability condition (P + 2 D of
  /// contact_stability_share: the stable step falls by sqrt(1 - share / 4)).
  static double largest_share(const Scene& scene);

  /// Sets the friction reference (positions, body displacements) to the state at a stage start.
  void start(const Vector& d_overlap, const std::vector<RigidBodyState>& bodies);
  /// Adds the contact forces at d to f_overlap and writes each body's contact force (summed over
  /// ranks) into bodies[b].force. Collective. Throws NumericalError when a free body is too
  /// light for its contact stiffness.
  void add_forces(const Vector& d_overlap, double dt, std::vector<RigidBodyState>& bodies,
                  Vector& f_overlap);
  /// The step is accepted: the friction state of the last evaluation becomes the reference.
  void commit(const std::vector<RigidBodyState>& bodies);
  /// Particles in contact at the last evaluation, summed over ranks (collective).
  long long active_count() const;
  /// Candidates (surface particles tested), summed over ranks (collective).
  long long candidate_count() const;
  /// The normal force on each rigid wall at the last evaluation (summed over ranks).
  const std::vector<double>& wall_forces() const { return wall_forces_; }

 private:
  struct Candidate {
    ParticleRow row;
    double mass = 0;
    std::array<double, 3> x_old{}, ft_old{}, x_new{}, ft_new{};
    bool active = false;
  };
  struct Pair {
    std::size_t body = 0;
    double penalty = 0, damping = 0;
    contact::Friction friction;
    std::array<double, 3> body_u_old{}, body_rotation_old{};
    std::vector<Candidate> candidates;
  };

  int dim_;
  const RigidBodies& bodies_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Pair> pairs_;
  std::vector<double> wall_forces_;
};

}  // namespace efg
