#include "run/ShellExplicitStage.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "contact/ShellRigidContact.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "drivers/EnergyBalanceCheck.hpp"
#include "drivers/StableTimeStep.hpp"
#include "parallel/NonFinite.hpp"
#include "parallel/ReproducibleSum.hpp"
#include "run/ShellStageInputs.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellMultipliers.hpp"

namespace efg {
namespace {

using Vector = FlatShellOperator::Vector;
constexpr int nd = shell_dofs_per_node;

// The dof of a non-finite displacement as "particle N (dof c)", or "" (collective).
std::string first_non_finite(const Vector& d) {
  const long long dof = non_finite_dof(d);
  if (dof < 0) return "";
  const char* const name[nd] = {"u", "v", "w", "theta_x", "theta_y"};
  return "particle " + std::to_string(dof / nd + 1) + " (" + name[dof % nd] + ")";
}

}  // namespace

ShellExplicitSummary run_shell_explicit_stage(const Model& model, const FlatShellOperator& op,
                                              const StageSpec& stage, double start, Vector& d,
                                              Vector& v, const ShellRecord& record) {
  const auto& scene = model.scene;
  const auto& settings = stage.settings;
  Vector mass = op.lumped_mass();
  mass.scale(settings["mass_scale"].as<double>());
  Vector inv_mass(mass.getMap());
  inv_mass.reciprocal(mass);

  const auto supports_at = [&](double time) { return shell_supports_at(scene, stage.name, time); };
  const auto supports_then = supports_at(start);
  ShellConstraints constraints(model, op, supports_then);
  ShellMultipliers multipliers(constraints, mass);
  const std::size_t supports = supports_then.size();
  // Supports held still keep their values and do no work: nothing to re-evaluate per step.
  const bool moving = shell_supports_move(scene, stage.name);
  std::vector<int> row_components;  // per collocation row, the component it holds
  for (const auto& [support, component] : constraints.row_supports())
    row_components.push_back(component);

  // Nitsche and penalty supports act as forces -r_w(d) (their stiffness in the stable step, their
  // work in the supports' work); transformation supports by the multipliers.
  const bool weak = constraints.weak();
  Vector r_weak(mass.getMap()), r_weak_old(mass.getMap());
  const auto internal_force = [&](const Vector& x, Vector& f) {
    op.internal_force(x, f);
    if (!weak) return;
    Vector r(f.getMap());
    constraints.weak_resistance(x, r);
    f.update(1.0, r, 1.0);
  };
  StableTimeStep stable(
      internal_force, mass, [&op](bool on) { op.set_elastic_probe(on); },
      stable_step_method(settings["stable_step"].as<std::string>()));
  ShellExplicitSummary summary;
  summary.dt_crit = stable.estimate(d);
  // rigid tools (contact/ShellRigidContact): their penalty springs reduce the step as walls do
  std::unique_ptr<ShellRigidContact> contact;
  if (ShellRigidContact::wanted(scene, stage.name)) {
    contact = std::make_unique<ShellRigidContact>(model, op, mass, stage.name);
    summary.dt_crit *= std::sqrt(1 - contact->stability_share() / 4);
  }
  summary.largest_frequency = stable.largest_frequency();
  const bool fixed = static_cast<bool>(settings["dt"]);
  const double dt =
      fixed ? settings["dt"].as<double>() : settings["dt_scale"].as<double>() * summary.dt_crit;
  if (fixed)
    refuse_unstable_dt(stage.name, dt, summary.dt_crit, start,
                       settings["allow_unstable_dt"].as<bool>());
  refuse_endless_stage(scene.file, stage.name, stage.end_time - start, dt, summary.dt_crit);
  summary.dt = dt;
  {
    std::ostringstream o;
    o << "stage '" << stage.name << "' (shells, explicit): stable time step " << summary.dt_crit
      << " (largest frequency " << summary.largest_frequency << " rad/time, rotary inertia "
      << "scaled to the particle spacing), dt = " << dt << ", " << multipliers.count()
      << " held dofs (Lagrange multipliers)" << (weak ? ", nitsche or penalty supports" : "");
    Log::info(o.str());
  }
  if (op.plastic())
    Log::warning("stage '" + stage.name +
                 "': J2 shells are experimental: a hinge forming at a held edge can grow an "
                 "odd-even pattern of the moments along the shell, which spoils the supports' "
                 "forces (docs/shells.md, \"J2 shells\")");

  const auto map = mass.getMap();
  Vector f_ext(map), f_ext_old(map), f_int(map), a(map), v_next(map), d_old(map), step(map),
      f_support(map), step_before(map);
  const ShellLineAndPointLoads edge_loads(model, op, stage.name);
  const bool follower = has_follower_pressure(scene, stage.name);
  const auto external_force = [&](double t, Vector& f) {
    f.putScalar(0.0);
    op.add_pressure(shell_pressure_at(model, stage.name, t), f);
    edge_loads.add(t, 1.0, f);
    if (follower)
      op.add_follower_pressure(shell_pressure_at(model, stage.name, t, 1.0, true), d, f);
  };
  // The nitsche and penalty supports' forces at the current step, and their impulse since the
  // last record (written as the interval's mean, as the multipliers' and the contacts' are:
  // instantaneous samples of a ringing press edge aliased to 3 % of its force).
  std::vector<double> weak_forces, weak_impulse;
  Vector f_contact(map), f_contact_old(map);
  double contact_dt = dt;  // the step that led to d (the contact's approach speed)
  if (contact) contact->start(start, dt);
  const auto accelerate = [&](const Vector& f, Vector& acc) {
    op.internal_force(d, f_int);
    if (contact) {  // the tools' push, an external force on the sheet
      contact->forces(d, contact_dt, f_contact);
      f_int.update(-1.0, f_contact, 1.0);
    }
    if (weak) {
      constraints.weak_resistance(d, r_weak, &weak_forces);
      f_int.update(1.0, r_weak, 1.0);
      constraints.commit();  // the J2 edge points' layers, as the points'
    }
    op.commit_state();  // every explicit step is accepted (J2 layers; nothing for elastic parts)
    acc.update(1.0, f, -1.0, f_int, 0.0);
    acc.elementWiseMultiply(1.0, inv_mass, acc, 0.0);
  };
  // E = 1/2 v . M v of the velocity at an integer step.
  const auto kinetic = [&](const Vector& vel) {
    Vector mv(map);
    mv.elementWiseMultiply(1.0, mass, vel, 0.0);
    return 0.5 * reproducible_dot(mv, vel);
  };
  // v_(n+1/2) from v_(n-1/2) and a_n over the mean of the two steps, then the constraints at
  // t_(n+1): the predicted d + dt v projected by the multipliers gives the velocity that keeps
  // them; f_support is their force -C^T lambda in the step.
  const auto next_velocity = [&](double dt_mean, double dt_next, double t_next) {
    if (moving) {
      auto g = constraints.collocation_values(supports_at(t_next));
      // finite rotations: d's rotation dofs are the step's rotation (accepted every step), so a
      // prescribed rotation's rows hold its change over the step (as in implicit stages)
      if (op.finite_rotations()) {
        const auto then = constraints.collocation_values(supports_at(t_next - dt_next));
        for (std::size_t k = 0; k < g.size(); ++k)
          if (row_components[k] >= shell_rx) g[k] -= then[k];
      }
      multipliers.set_values(g);
    }
    v_next.update(1.0, v, dt_mean, a, 0.0);
    Tpetra::deep_copy(step, d);
    step.update(dt_next, v_next, 1.0);
    f_support.putScalar(0.0);
    multipliers.correct(step, dt_next, &f_support);
    v_next.update(1.0 / dt_next, step, -1.0 / dt_next, d, 0.0);
  };

  double t = start, dt_prev = 0.0, external_work = 0.0;
  const double interval = stage.output_interval ? *stage.output_interval : stage.end_time - start;
  double next_output = start + interval;
  external_force(t, f_ext);
  accelerate(f_ext, a);
  weak_impulse.assign(weak_forces.size(), 0.0);
  const double energy0 = kinetic(v) + [&] {
    double e = op.strain_energy(d), all = 0;
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_SUM, 1, &e, &all);
    return all;
  }();
  // Nitsche supports with beta below the trace inverse estimate make the potential of the shell on
  // its supports (strain energy + their energy) unbounded below: the motion then grows without
  // bound while the balance still holds (the supports' work pays for it). That potential is
  // >= 0 for supports held at 0 and a coercive form (near 0 at worst when they move), so a
  // clearly negative one stops the stage where it happens.
  const auto refuse_non_coercive_supports = [&](double strain, double kin) {
    const double supports_energy = constraints.weak_energy(d), potential = strain + supports_energy;
    if (potential >= -0.05 * std::max({strain, kin, std::abs(supports_energy)})) return;
    std::string names;
    for (const auto& bc : scene.boundary_conditions)
      if (bc.stages.includes(stage.name) && bc.method == "nitsche")
        names += (names.empty() ? "'" : ", '") + bc.name + "'";
    std::ostringstream o;
    o << "stage '" << stage.name << "' (shells, explicit): the nitsche supports " << names
      << " are not coercive: strain energy " << strain << " plus their energy " << supports_energy
      << " is negative (kinetic energy " << kin << ") at step " << summary.steps << ", t = " << t
      << "; raise their penalty (alpha of beta = alpha s / h, default 100; docs/shells.md, "
         "\"Essential conditions\")";
    throw NumericalError(o.str());
  };
  // The balance error: the worst imbalance of a record over the largest energy of the stage
  // (relative to each record's own energies, the first records of a stage starting at rest
  // would divide the round-off of the first step's work by nearly nothing).
  double largest_energy = energy0, worst_imbalance = 0;
  EnergyBalanceCheck balance(stage.name, settings["energy_balance_limit"].as<double>());
  const auto account = [&](double kin) {
    double e = op.strain_energy(d), strain = 0;
    Teuchos::reduceAll(*map->getComm(), Teuchos::REDUCE_SUM, 1, &e, &strain);
    largest_energy = std::max({largest_energy, kin, strain, std::abs(external_work)});
    const double imbalance = std::abs(kin + strain - energy0 - external_work);
    worst_imbalance = std::max(worst_imbalance, imbalance);
    summary.energy_error = largest_energy > 0 ? worst_imbalance / largest_energy : 0.0;
    if (weak && !op.plastic()) refuse_non_coercive_supports(strain, kin);
    const double error = largest_energy > 0 ? imbalance / largest_energy : 0.0;
    if (balance.failed(error)) {
      std::ostringstream energies;
      energies << "kinetic " << kin << " + strain " << strain << " against initial " << energy0
               << " + work of loads and supports " << external_work;
      throw NumericalError(balance.message(error, summary.steps, t, energies.str(), ""));
    }
  };
  // The supports' forces written at a record are their mean since the previous record (the
  // impulse over the time between): a moving support drives the particles next to it at the
  // highest frequencies, and the step-to-step multipliers ring.
  double since = start;
  for (;;) {
    const bool last = t >= stage.end_time - 1e-12 * std::max(1.0, std::abs(stage.end_time));
    const double dt_next = last ? dt : std::min(dt, stage.end_time - t);
    next_velocity(0.5 * (dt_prev + dt_next), dt_next, t + dt_next);
    if (last || t >= next_output - 1e-9 * dt) {
      // The velocity at the integer step: the mean of the half steps around it.
      Vector v_n(map);
      v_n.update(0.5, v, 0.5, v_next, 0.0);
      if (last) Tpetra::deep_copy(v, v_n);
      const double kin = kinetic(v_n);
      account(kin);
      auto forces = multipliers.mean_support_forces(supports, t - since);
      if (weak) {  // the nitsche and penalty supports' mean forces since the last record
        for (std::size_t k = 0; k < weak_forces.size(); ++k)
          forces[k] +=
              t > since && k < weak_impulse.size() ? weak_impulse[k] / (t - since) : weak_forces[k];
        weak_impulse.assign(weak_forces.size(), 0.0);
      }
      if (contact) {  // then 3 per scene rigid body: the contact force on it, then its velocity
        for (double F : contact->mean_body_forces(t - since)) forces.push_back(F);
        for (double v_b : contact->body_velocities()) forces.push_back(v_b);
      }
      record(t, kin, external_work, forces);
      since = t;
      next_output += interval;
    }
    if (last) break;
    multipliers.accumulate_impulse(dt_next);
    for (std::size_t k = 0; k < weak_impulse.size(); ++k)
      weak_impulse[k] += weak_forces[k] * dt_next;
    if (contact) contact->accumulate(dt_next);
    Tpetra::deep_copy(d_old, d);
    d.update(dt_next, v_next, 1.0);
    if (contact) contact->move(t, dt_next);
    // The supports' work: their force at t_n over the mean of the steps around it (none for
    // supports held still, whose force is normal to every motion they allow).
    step.update(1.0, d, -1.0, d_old, 0.0);
    // Finite rotations: every step is accepted, the frames turn by the step's rotations
    // exp(dt w) and the rotation dofs return to 0 (the velocities, the angular velocity's
    // components in the particles' frames, stay: a frame turned about w keeps w's components;
    // the lumped rotary inertia is isotropic, so there is no gyroscopic term; Simo & Wong 1991).
    if (op.finite_rotations()) op.accept_rotations(d);
    if (moving) {
      step_before.update(1.0, step, 1.0);
      external_work += 0.5 * reproducible_dot(f_support, step_before);
      Tpetra::deep_copy(step_before, step);
    }
    Tpetra::deep_copy(v, v_next);
    t += dt_next;
    dt_prev = dt_next;
    ++summary.steps;
    const auto bad = first_non_finite(d);
    if (!bad.empty()) {
      std::ostringstream o;
      o << "stage '" << stage.name << "' (shells, explicit): the displacement of " << bad
        << " is not finite at step " << summary.steps << ", t = " << t << " (dt = " << dt
        << ", stable time step " << summary.dt_crit << ")";
      throw NumericalError(o.str());
    }
    Tpetra::deep_copy(f_ext_old, f_ext);
    external_force(t, f_ext);
    external_work += 0.5 * (reproducible_dot(f_ext_old, step) + reproducible_dot(f_ext, step));
    if (weak) {
      Tpetra::deep_copy(r_weak_old, r_weak);
      if (moving) constraints.set_edge_values(supports_at(t));
    }
    Tpetra::deep_copy(f_contact_old, f_contact);
    contact_dt = dt_next;
    accelerate(f_ext, a);
    if (contact) {  // the bodies' second half step, and their work on the sheet (trapezoid)
      contact->finish(t, dt_next);
      external_work +=
          0.5 * (reproducible_dot(f_contact_old, step) + reproducible_dot(f_contact, step));
    }
    if (weak)  // the supports' force -r_w over the step (trapezoid, as the loads')
      external_work -= 0.5 * (reproducible_dot(r_weak_old, step) + reproducible_dot(r_weak, step));
  }
  std::ostringstream o;
  o << "stage '" << stage.name << "' (shells, explicit) done: " << summary.steps
    << " steps, energy balance error " << summary.energy_error;
  Log::info(o.str());
  return summary;
}

}  // namespace efg
