#include "drivers/ExplicitDriver.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/ContactStiffness.hpp"
#include "core/DeviceArrays.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/Progress.hpp"
#include "drivers/ExplicitPasses.hpp"
#include "drivers/StableStepSchedule.hpp"
#include "parallel/Collective.hpp"
#include "parallel/ExitReport.hpp"
#include "parallel/LargestParticle.hpp"
#include "parallel/NonFinite.hpp"
#include "parallel/ReproducibleSum.hpp"

namespace efg {
namespace {
// Stops a running timer for its scope (and restarts it, also when an exception leaves it); a
// stopped one stays stopped.
struct PausedTimer {
  explicit PausedTimer(Teuchos::Time& t) : timer(t), running(t.isRunning()) {
    if (running) timer.stop();
  }
  ~PausedTimer() {
    if (running) timer.start();
  }
  PausedTimer(const PausedTimer&) = delete;
  PausedTimer& operator=(const PausedTimer&) = delete;
  Teuchos::Time& timer;
  const bool running;
};

// The stage's lumped mass: the row-sum mass times its mass_scale (uniform mass scaling).
Vector stage_mass(const ModelOperators& ops, const StageSpec& stage) {
  Vector mass = lumped_mass(ops);
  const double factor = stage.settings["mass_scale"].as<double>();
  if (factor != 1.0) {
    mass.scale(factor);
    std::ostringstream o;
    o << "stage '" << stage.name << "': masses scaled by " << factor
      << " (uniform mass scaling): the stable time step grows by " << std::sqrt(factor)
      << ", inertia forces by " << factor;
    Log::info(o.str());
  }
  return mass;
}

// The largest share of walls and contacts in the stability condition: a wall adds penalty /
// dt^2 to a particle's omega^2, a contact its spring and damper (contact_stability_share).
double largest_wall_penalty(const Scene& scene) {
  double p = PenaltyContact::largest_share(scene);
  for (const auto& w : scene.rigid_walls) p = std::max(p, w.penalty);
  return p;
}
}  // namespace

ExplicitDriver::ExplicitDriver(const ModelOperators& ops, const StageSpec& stage)
    : ops_(ops),
      stage_(stage),
      mass_(stage_mass(ops, stage)),
      inverse_mass_(mass_.getMap()),
      contact_(RigidContact::wanted(ops.model().scene)
                   ? std::make_unique<RigidContact>(ops, mass_, stage.name)
                   : nullptr),
      motion_(ops.model(), stage.name),
      supports_(ops, stage.name, stage.settings["transformation_traction"].as<bool>()),
      stable_(ops, mass_, largest_wall_penalty(ops.model().scene), extra_stiffness(),
              stable_step_method(stage.settings["stable_step"].as<std::string>())),
      folds_(ops.model(), stage.name),
      f_ext_(mass_.getMap()),
      f_ext_old_(mass_.getMap()),
      f_wall_(mass_.getMap()),
      f_wall_old_(mass_.getMap()),
      f_int_(mass_.getMap()),
      wall_overlap_(ops.model().maps.overlap_dofs),
      d_overlap_(ops.model().maps.overlap_dofs),
      f_viscous_(mass_.getMap()),
      f_viscous_old_(mass_.getMap()),
      f_support_(mass_.getMap()),
      f_support_old_(mass_.getMap()),
      delta_(mass_.getMap()),
      v_half_(mass_.getMap()),
      previous_d_(mass_.getMap()),
      previous_v_(mass_.getMap()),
      previous_a_(mass_.getMap()),
      damping_(mass_damping_of(ops, stage), mass_),
      spring_x_(ops.model().maps.overlap_dofs),
      spring_y_(ops.model().maps.overlap_dofs),
      spring_owned_(mass_.getMap()),
      mass_v_(mass_.getMap()) {
  inverse_mass_.reciprocal(mass_);
  // The trapezoids' forces, old and new, dotted in one pass (account_energy); swapped, not
  // copied, each step, so these addresses hold. Loads constant in the stage are assembled once:
  // old and new are the same bits, one dot serves both. The support forces of prescribed
  // motions alone are nonzero on their rows only (PrescribedMotion::support_work). Walls and
  // the bulk viscosity only where they exist: without them their forces stay zero, their work
  // too.
  constant_loads_ = ops_.loads().constant_in(stage_.name);
  if (!constant_loads_) work_forces_.push_back(&f_ext_old_);
  work_forces_.push_back(&f_ext_);
  if (supports_.active()) work_forces_.insert(work_forces_.end(), {&f_support_old_, &f_support_});
  if (contact_) work_forces_.insert(work_forces_.end(), {&f_wall_old_, &f_wall_});
  if (ops_.mixed()) work_forces_.insert(work_forces_.end(), {&f_viscous_old_, &f_viscous_});
  viscosity_linear_ = stage_.settings["bulk_viscosity_linear"].as<double>();
  viscosity_quadratic_ = stage_.settings["bulk_viscosity_quadratic"].as<double>();
}

std::vector<double> ExplicitDriver::acceleration(double time, double wall_dt, const Vector& d,
                                                 const Vector& v, Vector& a, Vector* v_end,
                                                 double half_dt) {
  if (!constant_loads_ || !loads_assembled_)
    ops_.loads().assemble(curve_factor(ops_.model().scene, time, 1.0, stage_.name), f_ext_);
  loads_assembled_ = true;
  ops_.internal_force(d, f_int_);
  if (ops_.mixed()) ops_.bulk_viscosity(v, viscosity_linear_, viscosity_quadratic_, f_viscous_);
  if (supports_.active()) {  // f_int_ carries the weak supports' resistance from here on
    supports_.set_time(time);
    f_int_.update(1.0, supports_.resistance(d), 1.0);
  }
  std::vector<double> wall_forces;
  if (contact_) {  // rigid walls and contacts: forces on the particles (else f_wall_ stays 0)
    f_wall_.putScalar(0.0);
    ops_.to_overlap(d, d_overlap_);
    wall_overlap_.putScalar(0.0);
    contact_->add_forces(d_overlap_, wall_dt, wall_overlap_);
    wall_forces = contact_->wall_forces();
    ops_.to_owned(wall_overlap_, f_wall_);
  }
  acceleration_from_forces(f_ext_, f_int_, contact_ ? &f_wall_ : nullptr,
                           ops_.mixed() ? &f_viscous_ : nullptr, inverse_mass_, a,
                           v_end ? &v : nullptr, half_dt, v_end);
  return wall_forces;
}

StableTimeStep::ExtraStiffness ExplicitDriver::extra_stiffness() {
  const bool springs = contact_ && contact_->material_frequency2() > 0;
  if (!supports_.active() && !springs) return {};
  return [this, springs](const Vector& d) {
    auto weak = supports_.active() ? supports_.stiffness_at(d) : StableTimeStep::StiffnessProduct{};
    return StableTimeStep::StiffnessProduct([this, weak, springs](const Vector& x, Vector& y) {
      if (weak) weak(x, y);
      if (!springs) return;
      ops_.to_overlap(x, spring_x_);
      spring_y_.putScalar(0.0);
      contact_->add_spring_stiffness(spring_x_, spring_y_);
      ops_.to_owned(spring_y_, spring_owned_);
      y.update(1.0, spring_owned_, 1.0);
    });
  };
}

double ExplicitDriver::stable_step(const Vector& d) {
  // StableTimeStep's eigenvalue has the material rule's springs in it (extra_stiffness: k_K
  // fixed by the parts, not by dt) and it takes the mass rule's share S: 2 / omega sqrt(1 -
  // S / 4). The springs' dampers add 4 D w dt (w^2 the largest k_K / m): the positive root of
  // omega^2 dt^2 + 4 D w dt = 4 - S (contact/ContactStiffness.hpp).
  const double dt_crit = stable_.estimate(d);
  const double w2 = contact_ ? contact_->material_frequency2() : 0.0;
  const double damping = contact_ ? contact_->material_damping() : 0.0;
  if (!(w2 > 0) || !(damping > 0)) return dt_crit;
  const double omega = stable_.largest_frequency();
  return std::min(dt_crit, contact::damped_stable_step(omega * omega, 4.0 * damping * std::sqrt(w2),
                                                       largest_wall_penalty(ops_.model().scene)));
}

std::string ExplicitDriver::particle_label(long long particle) const {
  const auto& mesh = ops_.model().mesh;
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::ostringstream o;
  o << "particle " << particle + 1;
  // (on a rank's part of a mesh read in slices the particle may be elsewhere)
  const auto node = mesh.node_of(particle);
  if (node < 0) return o.str();
  o << " (X = (";
  for (std::size_t k = 0; k < dim; ++k)
    o << (k ? ", " : "") << mesh.coordinates[static_cast<std::size_t>(node) * dim + k];
  o << "))";
  return o.str();
}

void ExplicitDriver::report_non_finite(const RunState& state, long long step) const {
  const long long any = non_finite_dof(state.d, &state.v);
  std::ostringstream o;
  o << "stage '" << stage_.name << "': a displacement or velocity is not finite at "
    << particle_label(any / ops_.model().mesh.dimension) << " at step " << step
    << ", t = " << state.time << "; the last good state is in the results";
  throw NumericalError(o.str());
}

void ExplicitDriver::report_energy_balance(const EnergyBalanceCheck& check, const RunState& state,
                                           long long step) const {
  // The particle where the energy from nowhere shows: the largest m |v|^2.
  Vector w(mass_.getMap());
  w.elementWiseMultiply(1.0, mass_, state.v, 0.0);
  w.elementWiseMultiply(1.0, w, state.v, 0.0);
  const auto peak = largest_particle_sum(w, ops_.model().mesh.dimension);
  std::ostringstream energies;
  energies << "kinetic " << state.kinetic << " + internal " << state.internal << " against initial "
           << state.initial_energy << " + work of loads and supports " << state.external_work
           << " + walls " << state.wall_work;
  throw NumericalError(check.message(
      state.balance_error(), step, state.time, energies.str(),
      peak.particle >= 0 ? "the largest kinetic energy is at " + particle_label(peak.particle)
                         : ""));
}

void ExplicitDriver::refuse_endless(double span, double dt, double dt_crit) const {
  refuse_endless_stage(ops_.model().scene.file, stage_.name, span, dt, dt_crit);
}

bool ExplicitDriver::account_energy(RunState& state, const Vector& delta_d) const {
  // Trapezoidal work of the external, support and wall forces over the step (the supports of
  // prescribed motions are external forces too): the dots of work_forces_ with delta_d.
  const auto sums = step_sums(work_forces_, delta_d, state.d, state.v);
  const auto& w = sums.work;
  std::size_t next = 0;
  const double ext_old = w[next];
  if (!constant_loads_) ++next;
  const double ext = w[next++];
  std::array<double, 2> support{};
  if (supports_.active()) {
    support = {w[next], w[next + 1]};
    next += 2;
  } else {
    support = motion_.support_work(f_support_old_, f_support_, delta_d);
  }
  state.external_work += 0.5 * (ext_old + ext) + 0.5 * (support[0] + support[1]);
  if (contact_) {
    state.wall_work += 0.5 * (w[next] + w[next + 1]);
    next += 2;
  }
  if (ops_.mixed()) state.damping_work += 0.5 * (w[next] + w[next + 1]);
  return sums.finite;
}

ExplicitDriver::StepPlan ExplicitDriver::plan_steps(const Vector& d, double start) {
  const double scale = stage_.settings["dt_scale"].as<double>();
  const bool fixed = static_cast<bool>(stage_.settings["dt"]);
  const double fixed_dt = fixed ? stage_.settings["dt"].as<double>() : 0.0;
  StepPlan plan;
  plan.dt_crit = stable_step(d);
  plan.dt = fixed ? fixed_dt : scale * plan.dt_crit;
  std::ostringstream o;
  o << "stage '" << stage_.name << "': stable time step " << plan.dt_crit << " (largest frequency "
    << stable_.largest_frequency() << " rad/time, " << stable_.source();
  if (contact_ && contact_->material_frequency2() > 0)
    o << ", contact springs included: alone up to " << std::sqrt(contact_->material_frequency2())
      << " rad/time";
  o << "), dt = " << plan.dt;
  Log::info(o.str());
  // Honest about the default's error: generalized values are not the physical ones.
  for (const auto& bc : ops_.model().scene.boundary_conditions)
    if (bc.type == "displacement" && bc.method == "transformation" &&
        bc.stages.includes(stage_.name))
      Log::info("stage '" + stage_.name + "': displacement condition '" + bc.name +
                "' (method transformation) prescribes the particles' generalized values here: "
                "stresses next to it are approximate (2-25 %, docs/boundary_conditions.md, "
                "\"Explicit stages\"); method nitsche enforces it exactly at a smaller stable "
                "step");
  if (fixed)
    refuse_unstable_dt(stage_.name, fixed_dt, plan.dt_crit, start,
                       stage_.settings["allow_unstable_dt"].as<bool>());
  refuse_endless(stage_.end_time - start, plan.dt, plan.dt_crit);
  return plan;
}

std::array<double, 3> ExplicitDriver::momentum(const Vector& mass_times_v) const {
  const int dim = ops_.model().mesh.dimension;
  std::array<double, 3> mine{}, all{};
  const auto mv = mass_times_v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < mv.extent(0); ++k)
    mine[k % static_cast<std::size_t>(dim)] += mv(k, 0);
  Teuchos::reduceAll(*mass_.getMap()->getComm(), Teuchos::REDUCE_SUM, 3, mine.data(), all.data());
  const auto bodies = contact_->bodies().momentum(contact_->states());
  for (std::size_t k = 0; k < 3; ++k) all[k] += bodies[k];
  return all;
}

void ExplicitDriver::energies(RunState& state) {
  mass_v_.elementWiseMultiply(1.0, mass_, state.v, 0.0);
  state.kinetic = 0.5 * reproducible_dot(mass_v_, state.v);
  if (contact_) {
    state.kinetic += contact_->kinetic_energy();
    state.momentum = momentum(mass_v_);
  }
  ops_.to_overlap(state.d, d_overlap_);
  const double mine = ops_.strain_energy(d_overlap_);
  Teuchos::reduceAll(*mass_.getMap()->getComm(), Teuchos::REDUCE_SUM, mine,
                     Teuchos::outArg(state.internal));
}

void ExplicitDriver::support_forces(const Vector& a_free) {
  // Without weak supports f_support_ and f_support_old_ (swapped each step) are only ever
  // written on the constrained rows: the rest stay zero and need no pass.
  motion_.support_force(mass_, a_free, f_support_, !supports_.active());
  if (supports_.active()) f_support_.update(-1.0, supports_.last(), 1.0);
}

void ExplicitDriver::start(RunState& state, double dt) {
  if (contact_) {
    ops_.to_overlap(state.d, d_overlap_);
    contact_->begin(state.bodies, state.contact_allowances, state.time, d_overlap_);
  }
  state.wall_forces = acceleration(state.time, dt, state.d, state.v, state.a);
  damping_.add_to_acceleration(state.v, state.a);
  if (contact_) state.bodies = contact_->states();
  support_forces(state.a);
  const Vector v_start(state.v, Teuchos::Copy);
  motion_.constrain_end(curve_factor(ops_.model().scene, state.time, 1.0), v_start, state.v,
                        state.a);
  energies(state);
  if (!state.energy_started) {
    // The first explicit stage, or one after an implicit stage: a static solve has no history of
    // forces, so its work is not in the account, and the account is re-based here with the work
    // so far kept: E_0 = E_kin + E_int + D - W_ext - W_wall (the first stage: E_kin + E_int).
    // Without it an explicit stage after an implicit one stopped as unstable at equilibrium.
    state.initial_energy = state.kinetic + state.internal + state.damping_work +
                           state.mass_damping_work - state.external_work - state.wall_work;
    state.energy_started = true;
  }
  state.dt = dt;
  state.reactions_from_driver = true;
}

void ExplicitDriver::restore_previous(RunState& state) const {
  if (contact_) {
    contact_->restore();
    state.bodies = contact_->states();
  }
  Tpetra::deep_copy(state.d, previous_d_);
  Tpetra::deep_copy(state.v, previous_v_);
  Tpetra::deep_copy(state.a, previous_a_);
}

void ExplicitDriver::advance(RunState& state, double step_dt, long long step,
                             const StateOutput& output) {
  const auto& scene = ops_.model().scene;
  const auto begin = curve_factor(scene, state.time, 1.0);
  const auto mid = curve_factor(scene, state.time + 0.5 * step_dt, 1.0);
  const auto at_end = curve_factor(scene, state.time + step_dt, 1.0);
  // The step's start is kept for a failed step (restore_previous) and the trapezoids' old forces
  // for the account by swapping, not copying: the state's vectors are all written anew below
  // (d, v from the kept start; a and the forces by acceleration, the support forces on the rows
  // they use), with the bits of the copies and updates this replaced (d + delta = 1 d + 1 delta).
  previous_d_.swap(state.d);
  previous_v_.swap(state.v);
  previous_a_.swap(state.a);
  // The predictor in one pass, then again on the rows whose v_half the motions prescribe.
  predict(step_dt, previous_d_, previous_v_, previous_a_, v_half_, delta_, state.d);
  motion_.constrain_velocity(begin, mid, at_end, step_dt, v_half_);
  predict_rows(motion_.rows(), step_dt, previous_d_, v_half_, delta_, state.d);
  if (!constant_loads_) f_ext_old_.swap(f_ext_);
  f_wall_old_.swap(f_wall_);
  f_support_old_.swap(f_support_);
  f_viscous_old_.swap(f_viscous_);
  ops_.solid().history().set_step_time(step_dt);
  if (contact_) contact_->move(state.time, step_dt);
  // An inverted point (det F <= 0) may show on one rank only: agree on it collectively, write
  // the last good state, and name the point, step and time.
  try {
    run_collectively(mass_.getMap()->getComm(), [&] {
      // The walls keep the stage's stiffness on a shortened last step: p m / step_dt^2 would
      // multiply the contact force of the same penetration (4.7x measured on the bar impact).
      state.wall_forces = acceleration(state.time + step_dt, wall_dt_, state.d, v_half_, state.a,
                                       &state.v, 0.5 * step_dt);
    });
  } catch (const std::exception& e) {
    const bool here = dynamic_cast<const NumericalError*>(&e) != nullptr;
    const std::string what = e.what();
    meet_with_current_failure();  // agreed above; the meeting makes it so whatever threw
    restore_previous(state);
    output(state);
    if (!here) throw;
    std::ostringstream why;
    why << "stage '" << stage_.name << "': " << what << " at step " << step
        << ", t = " << state.time + step_dt << "; the last good state is in the results";
    throw NumericalError(why.str());
  }
  damping_.end_step(step_dt, state.v, state.a);
  if (contact_) {
    const auto work = contact_->finish(step_dt);
    state.wall_work += work.contact;
    state.external_work += work.gravity;
  }
  support_forces(state.a);
  motion_.constrain_end(at_end, v_half_, state.v, state.a);
  state.time += step_dt;
  state.dt = step_dt;
  const bool finite = account_energy(state, delta_);
  state.external_work += motion_.kinetic_energy_change(mass_, previous_v_, state.v);
  state.mass_damping_work += damping_.work(step_dt, previous_v_, state.v);
  if (!finite) {
    // Write the last good state, then name the particle, step and time.
    RunState failed(state.d.getMap());
    Tpetra::deep_copy(failed.d, state.d);
    Tpetra::deep_copy(failed.v, state.v);
    failed.time = state.time;
    restore_previous(state);
    state.time -= step_dt;
    output(state);
    report_non_finite(failed, step);
  }
  // The step is accepted: its material history (computed with the force at d_n+1) is kept.
  ops_.solid().history().commit();
  supports_.commit_history(state.d);
  if (contact_) {
    contact_->commit();
    state.bodies = contact_->states();
  }
}

void ExplicitDriver::carry_contact_state(RunState& state) const {
  if (contact_) state.contact_allowances = contact_->allowances();
}

ExplicitSummary ExplicitDriver::run(RunState& state, const StateOutput& output, bool record_start) {
  const double start_time = state.time, end = stage_.end_time, span = end - start_time;
  const double interval = stage_.output_interval.value_or(span / 20);
  const double scale = stage_.settings["dt_scale"].as<double>();
  const bool fixed = static_cast<bool>(stage_.settings["dt"]);
  const bool allow_unstable = stage_.settings["allow_unstable_dt"].as<bool>();

  const auto plan = plan_steps(state.d, start_time);
  double dt_crit = plan.dt_crit, dt = plan.dt;
  wall_dt_ = dt;
  start(state, dt);
  // The steps' phase holds the steps and their guards alone: the stable-step estimates and the
  // records are phases of their own (`stable time step`, `output`).
  auto& steps_timer = *Teuchos::TimeMonitor::getNewCounter("efg: explicit time steps");
  auto record = [&] {
    // Constrained rows: the constraint's share R = -M a_free; the boundary terms (of every
    // condition, on every row they reach) are counted by their own condition's totals.
    Vector constraint(f_support_, Teuchos::Copy);
    if (supports_.active()) constraint.update(1.0, supports_.last(), 1.0);
    state.reactions = motion_.reactions(constraint);
    if (supports_.active()) {
      const auto weak = supports_.reactions();
      for (std::size_t c = 0; c < weak.size(); ++c)
        for (std::size_t k = 0; k < 3; ++k) state.reactions[c][k] += weak[c][k];
    }
    if (contact_) state.contact_penetrations = contact_->take_penetrations();
    const PausedTimer paused(steps_timer);
    output(state);
  };
  if (record_start) record();

  Progress progress("stage '" + stage_.name + "'", span);
  ExplicitSummary summary;
  summary.smallest_dt = summary.largest_dt = dt;
  summary.first_dt_crit = summary.smallest_dt_crit = dt_crit;
  summary.stable_step_source = stable_.source();
  const long long lanczos_at_start = stable_.lanczos_runs();
  double next_output = std::min(end, start_time + interval);
  double reference_energy = std::max(state.initial_energy, 1e-300);
  EnergyBalanceCheck balance(stage_.name, stage_.settings["energy_balance_limit"].as<double>());
  const double relaxed_ratio = stage_.settings["relaxation_kinetic_ratio"].as<double>();
  int relaxed_checks = 0;  // checks in a row at or below the ratio (dynamic relaxation)
  // Re-estimates follow the strain and erosion (drivers/StableStepSchedule); linear elastic
  // parts keep the plan's estimate.
  StableStepSchedule schedule(
      ops_, stage_, !fixed && !ops_.model().scene.every_part_linear_elastic(), state.d, dt_crit);
  // Trapezoids of the kinetic and internal energies over the records (quasi-static indicator).
  double kinetic_integral = 0, internal_integral = 0, last_record_time = start_time,
         last_kinetic = state.kinetic, last_internal = state.internal;
  Teuchos::TimeMonitor timer(steps_timer);
  while (state.time < end - 1e-12 * span) {
    bool estimate = false;
    if (schedule.checks(summary.steps)) {  // the strain checks: part of the estimate's phase
      const PausedTimer paused(steps_timer);
      estimate = schedule.due(summary.steps, state.d);
    }
    if (estimate) {
      const PausedTimer paused(steps_timer);  // the estimate: its own phase
      try {
        dt_crit = stable_step(state.d);
      } catch (const std::exception& e) {
        // Every rank takes this handler (a peer's failure too: a PeerFailure caught only by the
        // stage loop's handler would meet this rank there and then make other collective calls).
        meet_with_current_failure();  // before the collective write (a rank-local failure ends)
        output(state);
        if (dynamic_cast<const NumericalError*>(&e) == nullptr) throw;  // a peer's: as it is
        std::ostringstream why;
        why << "stage '" << stage_.name << "' at step " << summary.steps << ", t = " << state.time
            << ": " << e.what() << "; the last state is in the results";
        throw NumericalError(why.str());
      }
      ++summary.dt_estimates;
      dt = scale * dt_crit;
      summary.smallest_dt_crit = std::min(summary.smallest_dt_crit, dt_crit);
      wall_dt_ = dt;
      schedule.estimated(summary.steps, state.d, dt_crit);
      summary.lanczos_estimates = stable_.lanczos_runs() - lanczos_at_start;
    }
    const double step_dt = std::min(dt, end - state.time);
    advance(state, step_dt, summary.steps + 1, output);
    ++summary.steps;
    summary.smallest_dt = std::min(summary.smallest_dt, step_dt);
    summary.largest_dt = std::max(summary.largest_dt, step_dt);
    const bool due = state.time >= next_output - 1e-12 * span;
    if (due || allow_unstable || balance.due(summary.steps)) {
      energies(state);
      summary.worst_balance_error = std::max(summary.worst_balance_error, state.balance_error());
      reference_energy =
          std::max({reference_energy, state.initial_energy + std::abs(state.external_work) +
                                          std::abs(state.wall_work)});
      // Neither energy check in the first step of a stage: the force a contact or a moving
      // support first exerts at the end of step 1 gives the particles kinetic energy whose work
      // enters the account with step 2 (the trapezoid's displacement of step 1 is zero), and
      // against an account of zero that looked like a blow-up (a punch pressing a block at 0.8
      // of the critical step). A true instability needs dozens of steps to grow tenfold.
      const bool checked = summary.steps > 1;
      // An unstable step size shows as energy growing far beyond what the loads put in.
      if (checked && state.kinetic + state.internal > 10.0 * reference_energy &&
          state.balance_error() > 0.5) {
        output(state);
        std::ostringstream why;
        why << "stage '" << stage_.name << "': unstable: the energy grew to "
            << state.kinetic + state.internal << " (loads and initial state put in "
            << reference_energy << ") at step " << summary.steps << ", t = " << state.time
            << " with dt = " << step_dt;
        if (step_dt > dt_crit)
          why << " above the stable time step " << dt_crit;
        else  // the step is not the cause: energy from a source the account does not see
          why << " within the stable time step " << dt_crit
              << " (energy from an unaccounted force or a nonsymmetric operator, not the step)";
        throw NumericalError(why.str());
      }
      // energies() left d in d_overlap_: the background cells in the current configuration.
      folds_.check(d_overlap_, state, summary.steps, output);
      if (checked && balance.failed(state)) {
        output(state);
        report_energy_balance(balance, state, summary.steps);
      }
      relaxed_checks =
          relaxed_ratio > 0 && state.internal > 0 && state.kinetic <= relaxed_ratio * state.internal
              ? relaxed_checks + 1
              : 0;
      if (relaxed_checks >= 2) {
        std::ostringstream o;
        o << "stage '" << stage_.name << "': relaxed at step " << summary.steps
          << ", t = " << state.time << ": kinetic / internal energy "
          << state.kinetic / state.internal << " <= " << relaxed_ratio;
        Log::info(o.str());
        summary.relaxed = true;
        record();
        break;
      }
    }
    if (due) {
      const double span_since = state.time - last_record_time;
      kinetic_integral += 0.5 * span_since * (last_kinetic + state.kinetic);
      internal_integral += 0.5 * span_since * (last_internal + state.internal);
      last_record_time = state.time;
      last_kinetic = state.kinetic;
      last_internal = state.internal;
      if (state.balance_error() > 0.01)
        Log::warning("energy balance error " + std::to_string(100 * state.balance_error()) +
                     " % at t = " + std::to_string(state.time));
      record();
      next_output = std::min(end, next_output + interval);
    }
    progress.update(state.time - start_time);
  }
  progress.finish();
  if (contact_) summary.contact_penetration = contact_->stage_penetrations();
  carry_contact_state(state);
  if (internal_integral > 0)
    summary.kinetic_to_internal_mean = kinetic_integral / internal_integral;
  if (state.internal > 0) summary.kinetic_to_internal_end = state.kinetic / state.internal;
  return summary;
}

}  // namespace efg
