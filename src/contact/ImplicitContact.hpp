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
// load stepping with cutback carries its changes.
#pragma once

#include <array>
#include <vector>

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
  /// Displacements of every body at the last set_time.
  const std::vector<std::array<double, 3>>& body_displacements() const { return displacement_; }
  /// r -= phi F (overlap) at d.
  void add_residual(const Vector& d_overlap, Vector& r_overlap) const;
  /// K += dr/dd (assembly mode).
  void add_tangent(const Vector& d_overlap, FEMatrix& K) const;
  /// The contact force on every body at d (summed over ranks; collective).
  std::vector<BodyResultant> body_forces(const Vector& d_overlap) const;

 private:
  struct Candidate {
    ParticleRow row;
    double stiffness = 0;  ///< beta_J A_J
  };
  struct Pair {
    std::size_t body;
    const ContactSpec* spec;
    bool active = true;  ///< the contact acts in the current stage
    std::vector<Candidate> candidates;
  };
  /// Gap, normal and the curvature matrix (dn/dx) of candidate c of pair p at d.
  struct Touch {
    double gap = 0, normal[3] = {0, 0, 0}, dn[3][3] = {};
  };
  template <class View>
  Touch touch(const Pair& p, const Candidate& c, const View& d) const;

  int dim_;
  RigidBodies bodies_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::vector<Pair> pairs_;
  double t0_ = 0;
  std::vector<std::array<double, 3>> start_, displacement_;
};

}  // namespace efg
