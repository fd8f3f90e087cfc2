#include "run/RunReport.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/DeviceArrays.hpp"
#include "core/Errors.hpp"
#include "core/Threads.hpp"
#include "core/Version.hpp"
#include "io/WritePaths.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"
#include "run/RunSummary.hpp"

namespace efg {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream o;
  o << std::setprecision(10) << v;
  return o.str();
}

template <class T>
void write_list(std::ostream& o, const std::vector<T>& values) {
  o << "[";
  for (std::size_t i = 0; i < values.size(); ++i) o << (i ? ", " : "") << number(values[i]);
  o << "]";
}

// Per implicit stage: the linear solver, its setup time, and every Newton solve's residuals,
// linear iterations and achieved linear reductions (cut back attempts included).
void write_implicit_stages(std::ostream& o, const std::vector<ImplicitStageReport>& stages) {
  o << ",\n  \"implicit_stages\": [";
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const auto& st = stages[s].summary;
    o << (s ? ", " : "") << "{\"stage\": " << quoted(stages[s].stage)
      << ", \"linear_solver\": " << quoted(st.linear_solver)
      << ", \"linear_setup_seconds\": " << number(st.linear_setup_seconds)
      << ", \"load_steps\": " << st.steps << ", \"cutbacks\": " << st.cutbacks
      << ", \"newton_iterations\": " << st.newton_iterations
      << ", \"linear_iterations\": " << st.linear_iterations << ", \"newton_solves\": [";
    for (std::size_t k = 0; k < st.newton_records.size(); ++k) {
      const auto& r = st.newton_records[k];
      std::vector<double> its(r.linear_iterations.begin(), r.linear_iterations.end());
      o << (k ? ", " : "") << "{\"residuals\": ";
      write_list(o, r.residuals);
      o << ", \"linear_iterations\": ";
      write_list(o, its);
      o << ", \"linear_reductions\": ";
      write_list(o, r.linear_reductions);
      o << ", \"stopped_by\": " << quoted(r.reason) << "}";
    }
    o << "]}";
  }
  o << "]";
}

// Per explicit stage: its steps, the step sizes, the stable-step estimates, the worst energy
// balance error, the quasi-static indicator (kinetic over internal energy: time integrals over
// the stage and at its end), whether dynamic relaxation ended it, and per contact with a rigid
// body the deepest particle over the stage as a fraction of its spacing (contact_penetration),
// and per rigid wall (wall_penetration).
void write_explicit_stages(std::ostream& o, const Scene& scene,
                           const std::vector<ExplicitStageReport>& stages) {
  o << ",\n  \"explicit_stages\": [";
  for (std::size_t s = 0; s < stages.size(); ++s) {
    const auto& st = stages[s].summary;
    o << (s ? ", " : "") << "{\"stage\": " << quoted(stages[s].stage) << ", \"steps\": " << st.steps
      << ", \"smallest_dt\": " << number(st.smallest_dt)
      << ", \"largest_dt\": " << number(st.largest_dt)
      << ", \"first_stable_step\": " << number(st.first_dt_crit)
      << ", \"smallest_stable_step\": " << number(st.smallest_dt_crit)
      << ", \"stable_step_source\": " << quoted(st.stable_step_source)
      << ", \"stable_step_estimates\": " << st.dt_estimates
      << ", \"stable_step_lanczos_estimates\": " << st.lanczos_estimates
      << ", \"worst_energy_balance_error\": " << number(st.worst_balance_error)
      << ", \"kinetic_to_internal_mean\": " << number(st.kinetic_to_internal_mean)
      << ", \"kinetic_to_internal_end\": " << number(st.kinetic_to_internal_end)
      << ", \"relaxed\": " << (st.relaxed ? "true" : "false");
    o << ", \"contact_penetration\": {";
    bool first = true;
    for (std::size_t c = 0; c < scene.contacts.size(); ++c) {
      if (scene.contacts[c].rigid_body.empty()) continue;
      const auto& pen = st.contact_penetration;
      o << (first ? "" : ", ") << quoted(scene.contacts[c].name) << ": "
        << number(c < pen.size() ? pen[c] : 0.0);
      first = false;
    }
    o << "}, \"wall_penetration\": {";
    for (std::size_t w = 0; w < scene.rigid_walls.size(); ++w) {
      const auto& pen = st.contact_penetration;
      const auto at = scene.contacts.size() + w;
      o << (w ? ", " : "") << quoted(scene.rigid_walls[w].name) << ": "
        << number(at < pen.size() ? pen[at] : 0.0);
    }
    o << "}}";
  }
  o << "]";
}

}  // namespace

const std::vector<std::string>& report_phases() {
  static const std::vector<std::string> phases = {"scene and mesh",
                                                  "partition (Zoltan2 RCB)",
                                                  "neighbour search (ghosts, particles)",
                                                  "shape functions and integration",
                                                  "stiffness graph",
                                                  "internal force",
                                                  "tangent assembly",
                                                  "essential conditions",
                                                  "Newton iterations",
                                                  "linear solver setup",
                                                  "stable time step",
                                                  "explicit time steps",
                                                  "output",
                                                  "verification (error norms)"};
  return phases;
}

std::vector<ReferenceCheck> reference_checks(const ModelOperators& ops, const RunState& state,
                                             const std::vector<std::string>& global_names,
                                             const std::vector<double>& global_values) {
  const auto& model = ops.model();
  std::vector<ReferenceCheck> checks;
  if (!model.scene.verification || !model.scene.verification["reference_values"]) return checks;
  Vector d(model.maps.overlap_dofs), v(model.maps.overlap_dofs);
  ops.to_overlap(state.d, d);
  ops.to_overlap(state.v, v);
  const auto dim = static_cast<std::size_t>(model.mesh.dimension);
  for (const auto& r : model.scene.verification["reference_values"]) {
    ReferenceCheck c;
    c.name = r["name"].as<std::string>();
    c.quantity = r["quantity"].as<std::string>();
    c.reference = r["value"].as<double>();
    c.tolerance = r["tolerance"].as<double>();
    const auto at = c.quantity.find('@');
    if (at == std::string::npos) {
      const auto it = std::find(global_names.begin(), global_names.end(), c.quantity);
      if (it == global_names.end())
        throw InputError(model.scene.file + ": verification.reference_values '" + c.name +
                         "': unknown quantity '" + c.quantity +
                         "'; expected a global variable of the results or "
                         "<displacement|velocity>_<x|y|z>@<node set>");
      c.value = global_values[static_cast<std::size_t>(it - global_names.begin())];
    } else {
      const auto field = c.quantity.substr(0, at), set_name = c.quantity.substr(at + 1);
      const auto* set = model.mesh.find_node_set(set_name);
      const bool known =
          (field.rfind("displacement_", 0) == 0 || field.rfind("velocity_", 0) == 0) &&
          field.size() > 2 && field.back() >= 'x' &&
          static_cast<std::size_t>(field.back() - 'x') < dim;
      if (!set || !known)
        throw InputError(model.scene.file + ": verification.reference_values '" + c.name +
                         "': cannot evaluate '" + c.quantity +
                         "'; expected <displacement|velocity>_<x|y|z>@<node set of the mesh>");
      const auto k = static_cast<std::size_t>(field.back() - 'x');
      const auto values = (field[0] == 'd' ? d : v).getLocalViewHost(Tpetra::Access::ReadOnly);
      std::vector<char> in(model.mesh.node_count(), 0);
      for (auto n : set->nodes) in[static_cast<std::size_t>(n)] = 1;
      double local[2] = {0, 0}, total[2] = {0, 0};
      for (std::size_t p = 0; p < model.parts.size(); ++p) {
        const auto& part = model.parts[p];
        for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
          if (!in[static_cast<std::size_t>(part.cloud.mesh_node[j])]) continue;
          local[1] += 1;
          for (auto e = part.particle_values().offsets[j];
               e < part.particle_values().offsets[j + 1]; ++e) {
            const auto node = static_cast<std::size_t>(ops.solid().overlap_node(
                p)[static_cast<std::size_t>(part.particle_values().particles[e])]);
            local[0] += part.particle_values().values[e] * values(node * dim + k, 0);
          }
        }
      }
      Teuchos::reduceAll(*model.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM, 2, local, total);
      c.value = total[0] / std::max(1.0, total[1]);
    }
    checks.push_back(c);
  }
  return checks;
}

void write_run_report(const CommPtr& comm, const Model& model, const std::string& json_path,
                      const std::string& results_path, const RunState& state,
                      const std::optional<ErrorNorms>& errors,
                      const std::vector<ReferenceCheck>& checks, double total_seconds,
                      const std::vector<ImplicitStageReport>& implicit, const ProbeValues& probes,
                      const std::vector<MemoryPhase>& memory_phases,
                      const std::vector<std::pair<std::string, ProbeValues>>& probes_by_stage,
                      const std::vector<std::pair<std::string, ProbeValues>>& angles_by_stage,
                      const std::vector<ExplicitStageReport>& explicit_stages) {
  std::vector<double> local, global;
  for (const auto& phase : report_phases()) {
    const auto timer = Teuchos::TimeMonitor::lookupCounter("efg: " + phase);
    local.push_back(timer.is_null() ? 0.0 : timer->totalElapsedTime());
  }
  global.resize(local.size());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(local.size()), local.data(),
                     global.data());
  const long long memory = peak_memory_bytes();
  long long memory_max = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, memory, Teuchos::outArg(memory_max));
  // Rank 0 writes; a failed write (a full disk) is learned by every rank, which would otherwise
  // wait for rank 0 in the run summary's reductions.
  run_collectively(comm, [&] {
    fault_point("report");
    if (comm->getRank() != 0) return;
    write_then_rename(json_path, [&](std::ostream& o) {
      o << "{\n  \"scene\": " << quoted(model.scene.file)
        << ",\n  \"title\": " << quoted(model.scene.title) << ",\n  \"efg_version\": "
        << quoted(std::string(version_string) + " (" + git_describe + ")")
        << ",\n  \"results\": " << quoted(results_path) << ",\n  \"ranks\": " << comm->getSize()
        << ",\n  \"threads_per_rank\": " << threads_per_rank()
        << ",\n  \"execution_space\": " << quoted(ExecSpace::name())
        << ",\n  \"particles\": " << model.mesh.whole_node_count()
        << ",\n  \"dofs\": " << model.maps.owned_dofs->getGlobalNumElements()
        << ",\n  \"end_time\": " << number(state.time) << ",\n  \"phase_seconds\": {";
      for (std::size_t i = 0; i < global.size(); ++i)
        o << (i ? ", " : "") << quoted(report_phases()[i]) << ": " << number(global[i]);
      o << "},\n  \"total_seconds\": " << number(total_seconds)
        << ",\n  \"memory_high_water_bytes\": " << memory_max;
      if (!memory_phases.empty()) {
        o << ",\n  \"memory_by_phase\": [";
        for (std::size_t i = 0; i < memory_phases.size(); ++i)
          o << (i ? ", " : "") << "{\"phase\": " << quoted(memory_phases[i].phase)
            << ", \"bytes\": " << memory_phases[i].bytes
            << ", \"bytes_per_particle\": " << number(memory_phases[i].bytes_per_particle)
            << ", \"peak_bytes\": " << memory_phases[i].peak_bytes << "}";
        o << "]";
      }
      if (state.energy_started)
        o << ",\n  \"energy_balance_error\": " << number(state.balance_error());
      if (errors)
        o << ",\n  \"errors\": {\"exact_solution\": " << quoted(model.scene.exact_solution)
          << ", \"l2_rel_error\": " << number(errors->l2_relative)
          << ", \"energy_rel_error\": " << number(errors->energy_relative)
          << ", \"max_nodal_error\": " << number(errors->max_nodal)
          << (errors->pressure_relative >= 0
                  ? ", \"pressure_rel_error\": " + number(errors->pressure_relative)
                  : std::string())
          << "}";
      write_implicit_stages(o, implicit);
      write_explicit_stages(o, model.scene, explicit_stages);
      auto write_probes = [&](const ProbeValues& values) {
        o << "{";
        for (std::size_t i = 0; i < values.size(); ++i)
          o << (i ? ", " : "") << quoted(values[i].first) << ": " << number(values[i].second);
        o << "}";
      };
      if (!probes.empty()) {
        o << ",\n  \"probes\": ";
        write_probes(probes);
      }
      // At each stage's end: a springback is a difference of two stages' values.
      auto write_by_stage = [&](const char* key,
                                const std::vector<std::pair<std::string, ProbeValues>>& staged) {
        if (staged.empty()) return;
        o << ",\n  \"" << key << "\": {";
        for (std::size_t k = 0; k < staged.size(); ++k) {
          o << (k ? ", " : "") << quoted(staged[k].first) << ": ";
          write_probes(staged[k].second);
        }
        o << "}";
      };
      write_by_stage("probes_by_stage", probes_by_stage);
      write_by_stage("angles_by_stage", angles_by_stage);
      o << ",\n  \"reference_values\": [";
      for (std::size_t i = 0; i < checks.size(); ++i)
        o << (i ? ", " : "") << "{\"name\": " << quoted(checks[i].name)
          << ", \"quantity\": " << quoted(checks[i].quantity)
          << ", \"value\": " << number(checks[i].value)
          << ", \"reference\": " << number(checks[i].reference)
          << ", \"tolerance\": " << number(checks[i].tolerance)
          << ", \"passed\": " << (checks[i].passed() ? "true" : "false") << "}";
      o << "]\n}\n";
    });
  });
}

}  // namespace efg
