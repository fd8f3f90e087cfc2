// An explicit stage: central differences in velocity-Verlet form on the generalized particle
// dofs with the lumped mass,
//   v^(n+1/2) = v^n + dt/2 a^n,  d^(n+1) = d^n + dt v^(n+1/2),
//   a^(n+1) = M^-1 (f_ext - f_int(d^(n+1)) + f_wall),  v^(n+1) = v^(n+1/2) + dt/2 a^(n+1),
// with the same internal force function as the implicit driver. The time step is
// dt_scale x dt_crit (StableTimeStep), refreshed every dt_update_interval steps, or a fixed dt;
// a fixed dt above dt_crit runs only with allow_unstable_dt, and then an energy blow-up stops
// the run; a balance error above energy_balance_limit stops it too (EnergyBalanceCheck). Loads without a curve act at full value from the start (a step load).
// Every step checks for NaN or Inf; failures stop the run (exit 3) naming the particle, its
// position, the step and the time, after the last good state is written.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "contact/RigidContact.hpp"
#include "drivers/EnergyBalanceCheck.hpp"
#include "drivers/FoldGuard.hpp"
#include "drivers/MassDamping.hpp"
#include "drivers/PrescribedMotion.hpp"
#include "drivers/RunState.hpp"
#include "drivers/StableTimeStep.hpp"
#include "drivers/WeakSupports.hpp"
#include "operators/LumpedMass.hpp"

namespace efg {

using StateOutput = std::function<void(const RunState&)>;

struct ExplicitSummary {
  long long steps = 0;
  long long dt_estimates = 0;  ///< stable-step estimates during the stage (the plan's not counted)
  /// Of those, the ones that ran Lanczos steps (the others followed the rows' bounds, or were
  /// the bound, dense or converged: StableTimeStep::source).
  long long lanczos_estimates = 0;
  double smallest_dt = 0, largest_dt = 0, worst_balance_error = 0;
  /// Quasi-static indicator of a forming stage, from the records: the time integral of the
  /// kinetic energy over that of the internal energy (trapezoids), and their ratio at the end.
  double kinetic_to_internal_mean = 0, kinetic_to_internal_end = 0;
  bool relaxed = false;  ///< ended early by relaxation_kinetic_ratio (dynamic relaxation)
  /// The stable step at the stage's start, its smallest estimate, and what the first came from
  /// (StableTimeStep::source: dense, bound, lanczos, converged).
  double first_dt_crit = 0, smallest_dt_crit = 0;
  std::string stable_step_source;
  /// Per scene contact, then per rigid wall: the deepest particle in its rigid body (behind its
  /// wall) over the stage, as a fraction of its spacing (0 for contacts between parts or not in
  /// the stage).
  std::vector<double> contact_penetration;
};

class ExplicitDriver {
 public:
  ExplicitDriver(const ModelOperators& ops, const StageSpec& stage);

  /// Advances the state from state.time to the stage's end time. With `record_start`, the start
  /// state is written first, once its energies are known (a run's first record).
  ExplicitSummary run(RunState& state, const StateOutput& output, bool record_start = false);

  /// The stage's time step from state d at time `start`: dt_crit (StableTimeStep) and the dt
  /// used. Refuses (before any step, also for `efg check`) a fixed dt above dt_crit without
  /// allow_unstable_dt (NumericalError) and a stage needing more than 1e10 steps (InputError).
  struct StepPlan {
    double dt_crit = 0, dt = 0;
  };
  StepPlan plan_steps(const Vector& d, double start);

  const Vector& mass() const { return mass_; }
  /// a = M^-1 (f_ext(time) - f_int(d) - r_weak(d) + f_wall(d)), r_weak the weak supports'
  /// boundary terms; returns the wall forces. Exposed for tests. `wall_dt` sets the walls' penalty
  /// stiffness p m / wall_dt^2 (contact/PenaltyContact): the stage's step, not a shortened last
  /// step.
  /// With `v_end`, also v_end = v + half_dt a in the same pass (the step's corrector).
  std::vector<double> acceleration(double time, double wall_dt, const Vector& d, const Vector& v,
                                   Vector& a, Vector* v_end = nullptr, double half_dt = 0);

 private:
  /// dt_crit at d: StableTimeStep's, the eigenvalue of M^-1 (K + K_c) with the contacts'
  /// material-rule springs K_c in it and the mass-rule share of walls and contacts, lowered for
  /// the springs' dampers (contact/ContactStiffness.hpp).
  double stable_step(const Vector& d);
  /// The stiffness besides the solid's for StableTimeStep: the weak supports' and the contact
  /// springs' (empty without either).
  StableTimeStep::ExtraStiffness extra_stiffness();
  /// "particle N (X = (x, y, z))" of a global particle id, for messages.
  std::string particle_label(long long particle) const;
  [[noreturn]] void report_non_finite(const RunState& state, long long step) const;
  [[noreturn]] void report_energy_balance(const EnergyBalanceCheck& check, const RunState& state,
                                          long long step) const;  // collective
  /// Adds the step's work to the account; returns whether every d and v is finite (collective).
  bool account_energy(RunState& state, const Vector& delta_d) const;
  /// E_kin and E_int of the state (and the momentum, with rigid bodies).
  void energies(RunState& state);
  std::array<double, 3> momentum(const Vector& mass_times_v) const;
  /// Accelerations, support forces and energies of the start state.
  void start(RunState& state, double dt);
  double wall_dt_ = 0;  ///< the step size the walls' penalty is scaled with (the stage's dt)
  /// One velocity-Verlet step (step numbers the messages); on failure writes the last good state.
  void advance(RunState& state, double step_dt, long long step, const StateOutput& output);
  void restore_previous(RunState& state) const;  // also the rigid bodies
  /// At the stage's end: what the contacts hand to the next stage besides the bodies (the
  /// ignored initial depths).
  void carry_contact_state(RunState& state) const;
  /// f_support_ from the free acceleration: the prescribed motions' and the weak supports' forces.
  void support_forces(const Vector& a_free);

  const ModelOperators& ops_;
  const StageSpec& stage_;
  Vector mass_, inverse_mass_;
  std::unique_ptr<RigidContact> contact_;  ///< rigid walls, bodies and contacts, when any exist
  PrescribedMotion motion_;
  WeakSupports supports_;  ///< weak conditions, transformation traction (before stable_)
  StableTimeStep stable_;
  FoldGuard folds_;  ///< the guard against folded material (checked with the energies)
  Vector f_ext_, f_ext_old_, f_wall_, f_wall_old_, f_int_, wall_overlap_, d_overlap_;
  void refuse_endless(double span, double dt, double dt_crit) const;
  Vector f_viscous_, f_viscous_old_;  ///< bulk viscosity of mixed u-p cells (at v_n+1/2)
  double viscosity_linear_ = 0, viscosity_quadratic_ = 0;  ///< the stage's Q2, Q1
  Vector f_support_, f_support_old_;  ///< forces of the prescribed motions (their work is external)
  Vector delta_, v_half_, previous_d_, previous_v_, previous_a_;  ///< one step's scratch
  MassDamping damping_;                        ///< the stage's mass-proportional damping (off: 0)
  Vector spring_x_, spring_y_, spring_owned_;  ///< scratch of the contact springs' product
  Vector mass_v_;                              ///< M v (energies)
  std::vector<const Vector*> work_forces_;     ///< the forces whose work is accounted, old, new
  bool constant_loads_ = false;  ///< the stage's loads constant in time: f_ext_ assembled once
  bool loads_assembled_ = false;
};

}  // namespace efg
