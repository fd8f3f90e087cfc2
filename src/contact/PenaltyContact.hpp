// Penalty contact of the surface particles of deformable parts with rigid bodies, with Coulomb
// friction, for explicit stages (LS-DYNA's node-to-rigid-surface penalty contact in meshfree
// form); the planar rigid walls are the same contact, frictionless, on every particle of their
// node set. A candidate is an owned particle J on the boundary of a named part; its physical
// position is x_J = X_J + sum_I phi_I(X_J) d_I (shape functions do not interpolate). When x_J is
// inside the body (gap g < 0 along the outward normal n):
//   normal force    F_n = max(0, k (-g) - c v_n) n,   k the larger of penalty x m_J / dt^2 (m_J
//                   the lumped mass) and, with a rigid body, penalty_scale x K A_J / h_J (the
//                   part's bulk modulus; contact/ContactStiffness.hpp), c = 2 damping sqrt(k m_J)
//                   a viscous damping on the normal approach speed v_n over the last step (never
//                   pulling); the stable step is lowered for both (ContactStiffness.hpp);
//   friction        the elastic-slip return map of contact/CoulombFriction.hpp on the slip
//                   increment of the particle relative to the body over the step.
// The force F = F_n + F_t acts on the particle through its shape-function row (ParticleRow)
// and -F on the body: the
// momentum of particles plus free bodies is conserved to round-off. The friction state is
// committed when the step is accepted. Search: with analytic bodies, every candidate is tested
// each step, O(1) per particle (contact between deformable parts will need bins).
// Watched (contacts with rigid bodies; contact/PenetrationChecks.hpp): the deepest particle as a
// fraction of its spacing (history, report, a warning once above penetration_warning); a body
// that moves more than half a spacing against a part it is near in one step stops the run
// (tunnelling: the penalty cannot catch it); particles inside the body at the run's start stop
// it, or with initial_penetration: ignore their initial depth is their zero.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/CoulombFriction.hpp"
#include "contact/FacingArea.hpp"
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
  /// `initial` (the run's first contact stage: the bodies at their scene places): particles
  /// inside a body stop the run (NumericalError naming body, particle and depth) or, with
  /// initial_penetration: ignore, have their depth taken as zero. Collective.
  void start(const Vector& d_overlap, const std::vector<RigidBodyState>& bodies, bool initial);
  /// Adds the contact forces at d to f_overlap and writes each body's contact force (summed over
  /// ranks) into bodies[b].force. Collective. Throws NumericalError when a free body is too
  /// light for its contact stiffness.
  /// Throws NumericalError when a body passes more than half a spacing against a part it is
  /// near in one step (tunnelling); warns once per stage when a contact's deepest particle
  /// passes penetration_warning (`time`: the evaluation's, for the message).
  void add_forces(const Vector& d_overlap, double dt, double time,
                  std::vector<RigidBodyState>& bodies, Vector& f_overlap);
  /// The step is accepted: the friction state of the last evaluation becomes the reference.
  void commit(const std::vector<RigidBodyState>& bodies);
  /// Particles in contact at the last evaluation, summed over ranks (collective).
  long long active_count() const;
  /// Candidates (surface particles tested), summed over ranks (collective).
  long long candidate_count() const;
  /// The normal force on each rigid wall at the last evaluation (summed over ranks).
  const std::vector<double>& wall_forces() const { return wall_forces_; }
  /// The largest k_K / m_J of the material rule over the candidates (w^2 of ContactStiffness.hpp)
  /// and the damping of that contact; equal on every rank.
  double material_frequency2() const { return material_w2_; }
  double material_damping() const { return material_damping_; }
  /// y += K_c x: the material rule's springs as a stiffness on the generalized dofs (overlap
  /// vectors), each k_K,max I on its particle's position sum_I phi_I x_I (k n n^T is bounded by
  /// it along any normal): the stable step's eigenvalue problem takes them exactly
  /// (drivers/ExplicitDriver). Local; no communication.
  void add_spring_stiffness(const Vector& x_overlap, Vector& y_overlap) const;
  /// Per scene contact (scene order; 0 for contacts between parts or not in this stage), then
  /// per rigid wall: the deepest particle as a fraction of its spacing since the last call (then
  /// reset), and over the stage.
  std::vector<double> take_penetrations();
  std::vector<double> stage_penetrations() const;
  /// Per scene contact (empty for contacts between parts; as carried in for contacts not in this
  /// stage): each candidate particle's ignored initial depth now (initial_penetration: ignore),
  /// in candidate order.
  std::vector<std::vector<double>> allowances() const;
  /// A later stage's start: the depths an earlier stage still ignored, for the contacts active in
  /// both (the same candidates in the same order: built from the same scene contact); without
  /// it a stage boundary pushed the ignored depth out at once (a disc started 0.8 of the spacing
  /// inside a block: energy error 12.9 % in the second stage, exit 3).
  void carry_allowances(const std::vector<std::vector<double>>& allowances);

 private:
  struct Candidate {
    ParticleRow row;
    double mass = 0;
    /// the material rule's stiffness per facing area, scale K / h_J (0: the mass rule alone),
    /// and the particle's sides (contact/FacingArea.hpp)
    double k_per_area = 0;
    SideShares sides;
    double spacing = 0;      ///< its boundary spacing h_J
    std::size_t part = 0;    ///< index of its part in the model
    long long particle = 0;  ///< global particle id (messages)
    /// initial_penetration: ignore: the depth not pushed out (shrinks as the particle leaves)
    double allowance = 0, allowance_new = 0;
    std::array<double, 3> x_old{}, ft_old{}, x_new{}, ft_new{};
    bool active = false;
  };
  struct Pair {
    std::size_t body = 0;
    long contact = -1;  ///< index in scene.contacts; -1 for a rigid wall
    long wall = -1;     ///< index in scene.rigid_walls; -1 for a contact
    double penalty = 0, damping = 0, warning = 0;
    std::string initial = "stop";  ///< initial_penetration: stop | ignore | push
    bool warned = false;
    double peak = 0, stage_peak = 0;  ///< deepest fraction since the last take, over the stage
    contact::Friction friction;
    std::array<double, 3> body_u_old{}, body_rotation_old{};
    std::vector<Candidate> candidates;
  };
  /// At the run's start: particles inside a body stop the run or get their allowance
  /// (contact/InitialOverlaps.cpp). Collective.
  void initial_overlaps(const std::vector<RigidBodyState>& bodies);
  /// The slip of candidate c against pair's body over the step (contact/PenaltyForce.hpp).
  void slip(const Pair& pair, const Candidate& c, const std::vector<RigidBodyState>& bodies,
            double* s) const;
  /// After the step's forces: the deepest fractions (reduced) into the peaks, a warning once
  /// above the threshold, and the tunnelling check. Collective.
  void watch(std::vector<double>& deepest, std::vector<double>& travel, double time);
  /// A pair's place in take_penetrations: its contact's index, walls after the contacts.
  std::size_t penetration_slot(const Pair& pair) const;

  int dim_;
  const RigidBodies& bodies_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Pair> pairs_;
  std::vector<double> wall_forces_;
  std::vector<std::vector<double>> carried_allowances_;  ///< as given by the earlier stage
  const Model& model_;
  std::vector<double> part_spacing_;  ///< the smallest boundary spacing of each part (all ranks)
  double material_w2_ = 0, material_damping_ = 0;
};

}  // namespace efg
