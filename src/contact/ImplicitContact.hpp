// Penalty contact with fixed or prescribed (moving) rigid bodies in implicit (static) stages,
// frictionless (a prescribed body sits where its velocity x curve integral has taken it at the
// load step's time, from its place at the stage start): the
// surface particles of the named parts get, when their physical position x_J = X_J +
// sum_I phi_I(X_J) d_I is inside the body (gap g < 0, outward normal n), the force
//   F_J = beta_J A_J (-g) n,   beta_J = alpha E / h_J
// (A_J the particle's share of the part's boundary - each boundary side's measure split among
// its nodes, x thickness in 2D -, h_J the longest boundary side at it, E the part's Young's
// modulus, alpha the contact's implicit_penalty): a pressure from the material's stiffness, as
// Nitsche's beta, not from mass and time step. Residual r_I -= phi_I F_J; tangent
//   dr_I/dd_K = phi_I phi_K beta_J A_J (n n^T + g dn/dx),
// dn/dx = (I - n n^T) / rho for a sphere or 2D cylinder of radius rho at the point (the curved
// surface's term; 0 for planes and box faces). The active set follows the Newton iterate;
// load stepping with cutback carries its changes. A prescribed spin turns the body by
// angular_velocity x the curve's integral about its fixed axis (exact): the shape is evaluated
// turned, and friction sees the particle's slip against the turning surface.
// Friction (Coulomb, the return map of contact/CoulombFriction.hpp with the stick stiffness
// k_t = E A_J / h_J, stick_stiffness): the slip increment is the particle's motion relative to the body since the last
// accepted load step, the tangential force is recomputed from the committed one at every
// iterate (a cut-back step leaves the committed state as it was) and committed with the step.
// Its tangent, -dF_t/dx: stick k_t P_t (P_t = I - n n^T); slip
// mu (beta A t n^T + k_t F_n / |F_t*| (I - t t^T) P_t), t the slip direction, F_n the normal force,
// |F_t*| the trial force (nonsymmetric; the turn of the old force into a new tangent plane and
// the decay law's dependence on the slip are left out of it).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "contact/CoulombFriction.hpp"
#include "contact/ParticleRow.hpp"
#include "contact/RigidBodies.hpp"
#include "operators/CouplingGraph.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

class ImplicitContact {
 public:
  explicit ImplicitContact(const ModelOperators& ops);

  void add_couplings(CouplingGraph& graph) const;
  /// Stage start at t0 with the bodies' states carried over (empty: the scene's places).
  /// A stage begins at t0: the bodies' states carried over, and the contacts active in `stage`.
  void begin_stage(const std::vector<RigidBodyState>& carried, double t0,
                   const std::string& stage = "");
  /// The bodies' displacements at time t of the stage (prescribed motions).
  void set_time(double t);
  /// Force control (drivers/BodyForceBalance): body b displaced by `u` beyond its prescribed
  /// travel (a free body's place, found by balancing its static load), from now on.
  void set_offset(std::size_t b, const std::array<double, 3>& u);
  const RigidBodies& bodies() const { return bodies_; }
  /// A contact with body b acts in the current stage.
  bool acts_on(std::size_t b) const {
    return std::any_of(pairs_.begin(), pairs_.end(),
                       [b](const Pair& p) { return p.active && p.body == b; });
  }
  /// The contact stiffness of body b along the unit vector a at d, sum over its touching
  /// candidates of a^T B_J a (B_J = -dF_J/dx, the particle held): the stiffness the body would
  /// meet on rigid parts, an upper bound of the parts' (summed over ranks; collective).
  double body_stiffness(const Vector& d_overlap, std::size_t b, const double* a) const;
  /// The smallest gap of the candidates of body b at d (positive: nothing touches it), and the
  /// contact stiffness along a of the candidates at that gap (those that touch first).
  /// Summed over ranks; collective.
  struct FirstTouch {
    double gap = 0, stiffness = 0;
  };
  FirstTouch first_touch(const Vector& d_overlap, std::size_t b, const double* a) const;
  /// Displacements of every body at the last set_time.
  const std::vector<std::array<double, 3>>& body_displacements() const { return displacement_; }
  /// Rotations (sum of the turns; 2D: the angle about z) and 3D orientations of every body at
  /// the last set_time: prescribed spins turn the bodies, exactly, about their fixed axes.
  const std::vector<std::array<double, 3>>& body_rotations() const { return rotation_; }
  const std::vector<contact::Orientation>& body_orientations() const { return orientation_; }
  /// r -= phi F (overlap) at d.
  void add_residual(const Vector& d_overlap, Vector& r_overlap) const;
  /// K += dr/dd (assembly mode).
  void add_tangent(const Vector& d_overlap, FEMatrix& K) const;
  /// The contact force on every body at d (summed over ranks; collective).
  std::vector<BodyResultant> body_forces(const Vector& d_overlap) const;
  /// Friction: the reference of the slip, the state at d (a stage start).
  void start_friction(const Vector& d_overlap);
  /// Friction: the load step at d is accepted (its tangential forces become the committed ones).
  void commit(const Vector& d_overlap);
  bool has_friction() const;

 private:
  struct Candidate {
    ParticleRow row;
    double stiffness = 0;                     ///< beta_J A_J
    double size = 0;                          ///< h_J
    std::array<double, 3> x_old{}, ft_old{};  ///< friction: at the last accepted load step
  };
  struct Pair {
    std::size_t body;
    const ContactSpec* spec;
    bool active = true;  ///< the contact acts in the current stage
    contact::Friction friction;
    std::vector<Candidate> candidates;
  };
  /// Gap, normal and the curvature matrix (dn/dx) of candidate c of pair p at d; with friction
  /// the tangential force at d and the return map's state.
  struct Touch {
    double gap = 0, normal[3] = {0, 0, 0}, dn[3][3] = {};
    double ft[3] = {0, 0, 0};
    contact::CoulombState coulomb;
  };
  template <class View>
  Touch touch(const Pair& p, const Candidate& c, const View& d) const;
  /// B = -dF/dx of candidate c at its touch t (normal, curvature and friction terms).
  void particle_tangent(const Pair& pair, const Candidate& c, const Touch& t,
                        double (&B)[3][3]) const;
  static bool rubs(const Pair& p) { return p.friction.mu_s > 0 || p.friction.mu_d > 0; }
  /// The regularized stick's stiffness k_t = E A_J / h_J: the normal penalty's beta_J A_J without
  /// its factor implicit_penalty (the material's own stiffness over a boundary cell; the
  /// elastic slip mu F_n / k_t is mu p h / E). As stiff as the normal penalty, a stick -> slip
  /// switch moved particles 100x too far and Newton cycled between stick and slip.
  static double stick_stiffness(const Pair& p, const Candidate& c) {
    return c.stiffness / p.spec->implicit_penalty;
  }

  int dim_;
  RigidBodies bodies_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Pair> pairs_;
  double t0_ = 0, t_ = 0, t_committed_ = 0;
  std::vector<std::array<double, 3>> start_, displacement_, committed_displacement_;
  std::vector<std::array<double, 3>> offset_;  ///< force control: beyond the prescribed travel
  std::vector<std::array<double, 3>> start_rotation_, rotation_, committed_rotation_;
  std::vector<contact::Orientation> start_orientation_, orientation_;
};

}  // namespace efg
