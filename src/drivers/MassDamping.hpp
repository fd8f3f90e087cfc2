// Mass-proportional damping of an explicit stage (the role of LS-DYNA's *DAMPING_GLOBAL): a force
// -alpha M v on every particle, for quasi-static stages (forming, a settling preload) where the
// dynamic response is noise. In central differences the force at the step's end is implicit in
// v_{n+1} (a trapezoid: v_{n+1} - v_n = dt (a_f - alpha (v_n + v_{n+1}) / 2)), solved per dof:
//   v_{n+1} = (v_{n+1/2} + dt/2 a_f,n+1) / (1 + alpha dt / 2),   a_{n+1} = a_f,n+1 - alpha v_{n+1}.
// A free particle's velocity then falls by r = (1 - alpha dt/2) / (1 + alpha dt/2) per step
// (exp(-alpha dt) to O((alpha dt)^3)), unconditionally stable, and the work it dissipates,
// alpha dt v_avg . M v_avg with v_avg = (v_n + v_{n+1}) / 2, balances the kinetic energy lost
// exactly (multiply the trapezoid by M v_avg).
#pragma once

#include <Tpetra_Vector.hpp>

#include "operators/ModelOperators.hpp"
#include "scene/Scene.hpp"

namespace efg {

using Vector = Tpetra::Vector<>;

class MassDamping {
 public:
  /// `alpha` per dof in 1/time (0 where undamped: per-part damping); `mass` the lumped mass per
  /// dof.
  MassDamping(const Vector& alpha, const Vector& mass);
  bool active() const { return active_; }
  /// a -= alpha v (the damping force of a state, per unit mass).
  void add_to_acceleration(const Vector& v, Vector& a) const;
  /// Ends a step: `v` holds v_{n+1/2} + dt/2 a_f,n+1 and becomes v_{n+1}; `a` holds a_f,n+1 and
  /// becomes a_{n+1} (per dof).
  void end_step(double dt, Vector& v, Vector& a) const;
  /// The work dissipated over a step of length dt from v_old to v_new (collective).
  double work(double dt, const Vector& v_old, const Vector& v_new) const;

 private:
  Vector alpha_;
  bool active_;
  const Vector& mass_;
  mutable Vector average_, momentum_;  ///< scratch, allocated once
};

/// The stage's damping per owned dof: `damping` on the particles of the parts `damping_parts`
/// names (every part when it names none), 0 elsewhere. Throws InputError for an unknown part.
Vector mass_damping_of(const ModelOperators& ops, const StageSpec& stage);

}  // namespace efg
