#include "run/Simulation.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/MemoryAccount.hpp"
#include "drivers/ExplicitDriver.hpp"
#include "drivers/ImplicitDriver.hpp"
#include "io/ResultsOutput.hpp"
#include "parallel/Collective.hpp"
#include "parallel/ExitReport.hpp"
#include "run/InitialConditions.hpp"
#include "run/InitialState.hpp"
#include "run/OutputFields.hpp"
#include "run/RunHistory.hpp"
#include "run/RunRecorder.hpp"
#include "run/RunReport.hpp"
#include "run/RunSummary.hpp"
#include "run/ShellRun.hpp"
#include "scene/SceneAngles.hpp"
#include "verification/ErrorNorms.hpp"

namespace efg {
namespace {

// Error norms against the scene's exact solution, when it names one.
std::optional<ErrorNorms> verify(const Model& model, const ModelOperators& ops,
                                 const RunState& state) {
  if (model.scene.exact_solution.empty() || !ops.exact()) return std::nullopt;
  // Timed apart: the norms integrate the exact solution over every cell, which a run without
  // a verification block does not do (the time to a solution is the total less this).
  Teuchos::TimeMonitor timer(
      *Teuchos::TimeMonitor::getNewCounter("efg: verification (error norms)"));
  Vector d_overlap(model.maps.overlap_dofs);
  ops.to_overlap(state.d, d_overlap);
  const auto errors = error_norms(model, ops.solid(), ops.mixed(), d_overlap, *ops.exact());
  std::ostringstream o;
  o << "verification against " << model.scene.exact_solution << ": relative L2 displacement error "
    << errors.l2_relative << ", relative energy-norm error " << errors.energy_relative
    << ", largest nodal displacement error " << errors.max_nodal;
  if (errors.pressure_relative >= 0)
    o << ", relative L2 pressure error " << errors.pressure_relative;
  Log::info(o.str());
  return errors;
}

// The reference values of the scene at the final state, logged; the missed ones described.
std::vector<ReferenceCheck> check_references(const ModelOperators& ops, const RunState& state,
                                             const RunRecorder& recorder,
                                             std::vector<std::string>& failed) {
  const auto checks =
      reference_checks(ops, state, recorder.global_names(), recorder.last_globals());
  for (const auto& c : checks) {
    std::ostringstream o;
    o << "reference value '" << c.name << "' (" << c.quantity << "): " << c.value << " vs "
      << c.reference << " within " << 100 * c.tolerance
      << " %: " << (c.passed() ? "passed" : "FAILED");
    Log::info(o.str());
    if (!c.passed()) failed.push_back(o.str());
  }
  return checks;
}

// The probes' values at the recorder's last record (its history columns probe_*).
ProbeValues probe_values(const RunRecorder& recorder) {
  ProbeValues out;
  const auto& names = recorder.global_names();
  for (std::size_t i = 0; i < names.size() && i < recorder.last_globals().size(); ++i)
    if (names[i].rfind("probe_", 0) == 0) out.emplace_back(names[i], recorder.last_globals()[i]);
  return out;
}

// The scene's segment angles (scene/SceneAngles.hpp) from the probes' displacements `at_end`.
ProbeValues segment_angles(const Scene& scene, const ProbeValues& at_end) {
  auto value = [&](const std::string& column) {
    for (const auto& [name, v] : at_end)
      if (name == column) return v;
    throw std::logic_error("probe column " + column + " missing");
  };
  auto point = [&](const std::string& probe) {
    for (const auto& p : scene.probes)
      if (p.name == probe) return p.point;
    throw std::logic_error("angle of an unknown probe " + probe);
  };
  auto u = [&](const std::string& probe) {
    return std::array<double, 2>{value("probe_" + probe + "_ux"), value("probe_" + probe + "_uy")};
  };
  ProbeValues out;
  for (const auto& a : scene.angles)
    out.emplace_back(a.name, segment_angle_degrees(point(a.from), point(a.to), u(a.from), u(a.to)));
  return out;
}

}  // namespace

RunOutcome run_stages(const CommPtr& comm, const Model& model, const std::string& path,
                      double setup_seconds) {
  if (model.scene.has_shells()) return run_shell_stages(comm, model, path, setup_seconds);
  const auto started = std::chrono::steady_clock::now();
  // A scene builds only what it needs: the stiffness graph and solvers only for implicit stages.
  std::shared_ptr<ModelOperators> ops;
  std::unique_ptr<StaticProblem> problem;
  auto& memory = MemoryAccount::process();
  run_collectively(comm, [&] {
    ops = std::make_shared<ModelOperators>(model);
    memory.mark("operators");
    for (const auto& s : model.scene.stages)
      if (s.driver == "implicit" && !problem) problem = std::make_unique<StaticProblem>(ops);
    if (problem) memory.mark("stiffness graph and implicit conditions");
  });
  RunRecorder recorder(comm, model, *ops, problem.get(), path);
  memory.mark("output");
  RunState state(model.maps.owned_dofs);
  apply_initial_conditions(model, state);
  apply_initial_state(model, ops->solid(), state);  // a restart: the record replaces them
  auto write = [&](const RunState& s) { recorder.write(s); };
  // A numerical failure on any rank keeps the records so far in the .part files, on all ranks.
  // Every failure of a stage meets the other ranks before the collective clean-up.
  auto guarded = [&](const std::function<void()>& work) {
    try {
      work();
    } catch (...) {
      // Keeping the records is collective: a failure of this rank alone stops at the meeting
      // (the others never come) and the watchdog ends the run with its message. A numerical
      // failure keeps the records so far; any other leaves nothing (the writers remove their
      // .part files: bad input writes nothing).
      if (meet_with_current_failure().code == static_cast<int>(ExitCode::numerical))
        recorder.keep_partial();
      throw;
    }
  };
  const double first_end = model.scene.stages.empty() ? 1.0 : model.scene.stages.front().end_time;
  std::vector<ImplicitStageReport> implicit_reports;
  std::vector<ExplicitStageReport> explicit_reports;
  std::vector<std::pair<std::string, ProbeValues>> probes_by_stage, angles_by_stage;
  // The first record: an explicit first stage writes it itself, once the start energies are
  // known (written here it would show a kinetic energy of 0 with a nonzero initial velocity).
  const bool explicit_first =
      !model.scene.stages.empty() && model.scene.stages.front().driver == "explicit";
  if (!explicit_first) guarded([&] { write(state); });
  for (const auto& stage : model.scene.stages) {
    Log::info("stage '" + stage.name + "' (" + stage.driver +
              "), t = " + std::to_string(state.time) + " to " + std::to_string(stage.end_time));
    guarded([&] {
      if (stage.driver == "implicit") {
        state.v.putScalar(0.0);
        state.a.putScalar(0.0);
        state.reactions_from_driver = false;
        problem->begin_stage(state.bodies, state.time, stage.name, &state.d);
        ImplicitDriver driver(*problem, stage, state.time, first_end);
        const auto s = driver.run(state.d, [&](double t, const Vector&) {
          state.time = t;
          problem->set_time(t);  // the bodies where the recorded step left them
          const auto forces = problem->body_forces(state.d);
          // After the walls' normal forces, 3 per contact between deformable parts.
          const auto between_parts = problem->part_contact_forces(state.d);
          if (!between_parts.empty()) {
            const auto walls = model.scene.rigid_walls.size();
            state.wall_forces.resize(walls + between_parts.size(), 0.0);
            std::copy(between_parts.begin(), between_parts.end(),
                      state.wall_forces.begin() + static_cast<std::ptrdiff_t>(walls));
          }
          const auto places = problem->body_displacements();
          const auto turns = problem->body_rotations();
          const auto orientations = problem->body_orientations();
          if (!forces.empty()) state.bodies.resize(forces.size());
          for (std::size_t b = 0; b < forces.size(); ++b) {
            state.bodies[b].force = forces[b].force;
            state.bodies[b].moment = forces[b].moment;
            state.bodies[b].displacement = places[b];
            state.bodies[b].rotation = turns[b];
            state.bodies[b].orientation = orientations[b];
            state.bodies[b].velocity = {0.0, 0.0, 0.0};  // static
          }
          write(state);
        });
        implicit_reports.push_back({stage.name, s});
        state.energy_started = false;  // the next explicit stage re-bases the energy account
        Log::info("stage '" + stage.name + "' done: " + std::to_string(s.steps) + " steps, " +
                  std::to_string(s.cutbacks) + " cutbacks, " + std::to_string(s.newton_iterations) +
                  " Newton iterations, " + std::to_string(s.linear_iterations) +
                  " linear iterations");
      } else {
        std::unique_ptr<ExplicitDriver> driver;
        run_collectively(comm, [&] { driver = std::make_unique<ExplicitDriver>(*ops, stage); });
        const auto s = driver->run(state, write, &stage == &model.scene.stages.front());
        explicit_reports.push_back({stage.name, s});
        std::ostringstream o;
        o << "stage '" << stage.name << "' done: " << s.steps << " steps, dt " << s.smallest_dt
          << " to " << s.largest_dt << ", worst energy balance error "
          << 100 * s.worst_balance_error << " %, kinetic / internal energy "
          << s.kinetic_to_internal_mean << " (time integrals over the stage), "
          << s.kinetic_to_internal_end << " at its end, " << s.dt_estimates
          << " stable-step re-estimates (" << s.lanczos_estimates << " with Lanczos steps)";
        Log::info(o.str());
      }
    });
    state.time = stage.end_time;
    memory.mark("stage '" + stage.name + "' (" + stage.driver + ")");
    // The probes where the stage left them (a springback is the difference of two stages').
    auto at_end = probe_values(recorder);
    if (!model.scene.angles.empty()) {
      auto angles = segment_angles(model.scene, at_end);
      for (const auto& [name, degrees] : angles)
        Log::info("  angle '" + name + "' at the end of stage '" + stage.name +
                  "': " + std::to_string(degrees) + " degrees");
      angles_by_stage.emplace_back(stage.name, std::move(angles));
    }
    if (!at_end.empty()) probes_by_stage.emplace_back(stage.name, std::move(at_end));
  }
  RunOutcome outcome;
  outcome.errors = verify(model, *ops, state);
  recorder.close();
  outcome.records = recorder.records();
  const auto checks = check_references(*ops, state, recorder, outcome.failed_checks);
  const double seconds =
      setup_seconds +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // The probes' values of the last record (history columns probe_*), logged and reported.
  const auto probes = probe_values(recorder);
  for (const auto& [name, value] : probes) {
    std::ostringstream o;
    o.precision(10);
    o << name << " = " << value;
    Log::info(o.str());
  }
  const auto memory_phases = memory_by_phase(comm, model);
  write_run_report(comm, model, path + ".report.json", path, state, outcome.errors, checks, seconds,
                   implicit_reports, probes, memory_phases, probes_by_stage, angles_by_stage,
                   explicit_reports);
  Log::info("run report: " + path + ".report.json");
  return outcome;
}

}  // namespace efg
