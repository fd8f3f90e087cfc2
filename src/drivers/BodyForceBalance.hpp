// Force control of free rigid bodies in implicit (static) stages: a blank holder pressed onto a
// sheet by a given force, a weight resting on a part. Such a body has no inertia to integrate;
// its place s (a displacement along the axis a of its load L, contact/RigidBodies::
// static_load_axis; held across it and against rotation, as a holder on its guides) is the
// unknown that makes its contact forces balance the load:
//   R(s) = a . (L(t) + F_c(d(s), s)) = 0,
// F_c the force of the particles on the body, d(s) the parts' equilibrium with the body held at
// s (Newton, drivers/NewtonSolver). R is the Schur complement of the coupled system on the
// body's dof, [K c; c^T k] (block elimination, or bordering): Newton on s uses its slope
//   dR/ds = a . (dF_c/ds + dF_c/dd dd/ds),   K dd/ds = -dr/ds,
// the parts' response dd/ds solved with the stage's own linear solver on the Jacobian at d
// (NewtonSolver::solve_tangent), the derivatives along s taken as differences over a step
// delta = 1e-4 (|s| + |L| / k), k = sum a^T B_J a the contact's stiffness with the parts held
// rigid (the contact forces are linear in s on a fixed active set). The particles then move with the
// body, d += dd/ds ds, so that Newton on the parts starts from the coupled problem's own Newton
// step: the monolithic solution without the body's dof in the particles' matrix (one dense row
// and column coupling every contact particle across the ranks). Kept inside the bracket of a
// sign change of R once one is known (bisection otherwise). A body that touches nothing is moved
// along its load by the nearest gap and on by the penetration that would carry the load on the
// first particles it meets. Several bodies: each by its own slope (their coupling through the
// parts only slows the iteration).
// Converged when |R| <= 1e-8 max(|L|, the Newton test's force scale) for every body.
#pragma once

#include <array>
#include <vector>

#include "drivers/NewtonSolver.hpp"
#include "drivers/StaticProblem.hpp"

namespace efg {

class BodyForceBalance {
 public:
  /// The free bodies of `problem`'s contacts (none: inactive). `where` names the stage.
  BodyForceBalance(StaticProblem& problem, std::string where);

  bool active() const { return !bodies_.empty(); }
  /// Newton's solve of the load step ending at `time` (drivers/NewtonSolver::solve_predicted's
  /// arguments) with every force-controlled body moved to where its contact forces balance its
  /// load (x `no_curve` without a curve). The result sums the Newton solves it took; not
  /// converged when a Newton solve failed or the bodies did not balance (a cutback retries).
  NewtonResult solve(NewtonSolver& newton, Vector& d, const Vector& increment, double ratio,
                     double time, double no_curve);
  /// The load step is accepted: the bodies' places become the start of the next one.
  void commit();

 private:
  struct Body {
    std::size_t index = 0;
    std::array<double, 3> axis{};
    double committed = 0, last_increment = 0;  ///< s at the last accepted step, and its change
    // Within one load step:
    double s = 0, residual = 0;
    double below = 0, above = 0;  ///< a bracket: R > 0 at `below`, R < 0 at `above`
    bool has_below = false, has_above = false;
    double gap_before_approach = 0;  ///< approaching: the nearest gap before the last move
    bool approaching = false;
    std::array<double, 3> load{};   ///< L at the load step's time
    double along = 0;               ///< a . L
    Teuchos::RCP<Vector> response;  ///< dd/ds at the last place (null: none)
  };
  void place(const Body& b, double s);
  /// R of body b from the contact forces on every body.
  static double residual(const Body& b, const std::vector<BodyResultant>& forces);
  /// The next s of body b (Newton on its Schur complement, bisection, or an approach move) at
  /// the converged d; b.response gets dd/ds there (or null).
  double next_place(Body& b, NewtonSolver& newton, const Vector& d);

  StaticProblem& problem_;
  std::string where_;
  std::vector<Body> bodies_;
  Vector d_overlap_, r0_, r1_, moved_;
};

}  // namespace efg
