// When an explicit stage re-estimates its stable time step (docs/explicit.md, "Time step").
//
// The stable step follows the deformation: it is re-estimated when the strain since the last
// estimate, max |d (d - d_est) / dx| over the finite-strain parts' points (in the current
// configuration: the stiffness of a crushed foam grows as 1 / stretch^2), reaches
// dt_update_strain (their stiffness, and so omega_max, changes with strain; a small-strain part's
// does not: elastic probes take plasticity out, contact and walls enter by constant terms), when
// points have eroded since (the stiffness falls: the step may grow, and with every point eroded
// the stage stops), or after dt_update_interval steps. The strain is measured at steps predicted
// from its growth so far (half the remaining way, linearly, at most doubling the distance to the
// last estimate): a few gradient passes per estimate, not one per step. An impact that shrinks
// the stable step tenfold within a few dozen steps (the Taylor bar) is followed at once; a steady
// run pays for a few estimates.
//
// The strain interval adapts to what the estimates show: it is dt_update_strain times a factor
// that aims at a change of the stable step of kTargetChange per interval (the step is taken at
// 0.858 of the estimate, so a few per cent between estimates stay inside the margin), at most
// doubling per estimate and at most kWidest times dt_update_strain, and back to 1 at once when
// the step moved by more. The steel block of bench/stable_step.sh, whose step falls 21 % over
// its crush, re-estimated 34 times at a fixed 0.02. Linear elastic parts keep the plan's estimate: their K is
// constant, so is omega_max of M^-1 K; at 1e6 particles each re-estimate took 9 s, some 16 steps'
// worth.
#pragma once

#include "operators/ModelOperators.hpp"
#include "scene/Scene.hpp"

namespace efg {

class StableStepSchedule {
 public:
  /// `active`: re-estimates at all (not with a fixed dt, nor when every part is linear elastic);
  /// d: the displacements of the plan's estimate, dt_crit its result.
  StableStepSchedule(const ModelOperators& ops, const StageSpec& stage, bool active,
                     const Vector& d, double dt_crit);
  /// Whether due() measures the strain after `steps` steps (otherwise it returns false at once).
  bool checks(long long steps) const { return active_ && steps >= next_check_; }
  /// Whether the stable step is to be re-estimated after `steps` steps at displacements d
  /// (collective).
  bool due(long long steps, const Vector& d);
  /// A re-estimate gave `dt_crit` after `steps` steps at d.
  void estimated(long long steps, const Vector& d, double dt_crit);
  /// The strain interval now in use (dt_update_strain times the adaptive factor).
  double strain_interval() const { return update_strain_ * widening_; }

 private:
  const ModelOperators& ops_;
  bool active_;
  double update_strain_;
  double widening_ = 1.0;    ///< the adaptive factor on update_strain_
  double last_dt_crit_ = 0;  ///< the last estimate (0 before the plan's is known)
  long long refresh_;
  Vector d_estimated_, change_;
  long long estimated_at_ = 0, next_check_ = 1, eroded_at_estimate_ = 0, eroded_ = 0;
};

}  // namespace efg
