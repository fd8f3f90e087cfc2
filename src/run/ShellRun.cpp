#include "run/ShellRun.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "io/ResultsOutput.hpp"
#include "io/WritePaths.hpp"
#include "mesh/NodalVolume.hpp"
#include "mesh/SurfaceChart.hpp"
#include "model/Curves.hpp"
#include "model/PointOwner.hpp"
#include "parallel/Collective.hpp"
#include "parallel/ExitReport.hpp"
#include "run/ShellExplicitStage.hpp"
#include "run/ShellImplicitStage.hpp"
#include "run/ShellStageInputs.hpp"
#include "shells/ShellConstraints.hpp"
#include "shells/ShellReference.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;
// Probe columns: the five physical values and the bending moments at the point.
constexpr int probe_columns = nd + 3;
const char* const probe_names[probe_columns] = {"ux", "uy", "uz", "rx", "ry", "mxx", "myy", "mxy"};

// Probe columns at each probe point (collective): u^h of the five fields and the moments:
// elastic parts M = D kappa with the curvature from the direct gradients of the rotations there;
// J2 parts (whose moments need a layer history, kept at the integration points only) and finite
// rotations (rotation dofs since the last step) the moments of the nearest integration point of
// the part on the probe's rank, and with finite rotations the rotations of the director there.
// `point_resultants`: FlatShellOperator::resultants at d (needed when a part is J2).
std::vector<double> probe_values(const Model& model, const FlatShellOperator::Vector& d_owned,
                                 const FlatShellOperator& op,
                                 const std::vector<double>& point_resultants) {
  std::vector<double> local(model.scene.probes.size() * probe_columns, 0.0),
      global(local.size(), 0.0);
  FlatShellOperator::Vector d_overlap(op.maps().overlap_dofs);
  op.to_overlap(d_owned, d_overlap);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < model.scene.probes.size(); ++i) {
    const auto& probe = model.scene.probes[i];
    const int p = evaluating_part(model, probe.point.data());
    if (p < 0) continue;
    const auto& cloud = model.parts[static_cast<std::size_t>(p)].cloud;
    const auto v = evaluate_shape_functions(cloud, probe.point.data(), 1, true, [&](std::size_t) {
      return "probe '" + probe.name + "'";
    });
    double* out = &local[i * probe_columns];
    double grad_rx[2] = {0, 0}, grad_ry[2] = {0, 0};
    std::vector<int> lids;  // finite rotations: the rotation from the reference director
    for (auto k = v.neighbors.offsets[0]; k < v.neighbors.offsets[1]; ++k) {
      const auto node = cloud.mesh_node[static_cast<std::size_t>(v.neighbors.particles[k])];
      const auto lid = static_cast<std::size_t>(
          op.maps().overlap_nodes->getLocalElement(global_node_id(model, node)));
      for (std::size_t c = 0; c < nd; ++c) out[c] += v.phi[k] * d(lid * nd + c, 0);
      lids.push_back(static_cast<int>(lid));
      for (std::size_t a = 0; a < 2; ++a) {
        grad_rx[a] += v.grad[2 * k + a] * d(lid * nd + shell_rx, 0);
        grad_ry[a] += v.grad[2 * k + a] * d(lid * nd + shell_ry, 0);
      }
    }
    if (op.finite_rotations())
      op.physical_rotation(lids.data(), v.phi.data() + v.neighbors.offsets[0], lids.size(), d,
                           out[shell_rx], out[shell_ry]);
    if (op.plastic_part(static_cast<std::size_t>(p)) || op.finite_rotations()) {
      double nearest = -1;
      for (std::size_t r = 0; r < cloud.owned_count; ++r) {
        const double dx = cloud.position[2 * r] - probe.point[0],
                     dy = cloud.position[2 * r + 1] - probe.point[1];
        if (nearest >= 0 && dx * dx + dy * dy >= nearest) continue;
        nearest = dx * dx + dy * dy;
        const auto row = static_cast<std::size_t>(
            op.maps().owned_nodes->getLocalElement(global_node_id(model, cloud.mesh_node[r])));
        for (std::size_t c = 0; c < 3; ++c)
          out[nd + c] = point_resultants[row * shell_strains + 3 + c];
      }
      continue;
    }
    const double kappa[3] = {grad_ry[0], -grad_rx[1], grad_ry[1] - grad_rx[0]};
    const auto part = static_cast<std::size_t>(p);
    const auto section = op.section(  // at the probe's thickness
        part,
        op.thickness_at(part, lids.data(), v.phi.data() + v.neighbors.offsets[0], lids.size()));
    const auto& D = section.bending;
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t c = 0; c < 3; ++c) out[nd + r] += D[r][c] * kappa[c];
  }
  if (!local.empty())
    Teuchos::reduceAll(*model.maps.owned_nodes->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(local.size()), local.data(), global.data());
  return global;
}

struct StageResult {
  std::string name;
  double time = 0, seconds = 0, strain_energy = 0, largest_deflection = 0;
  long long dofs = 0;
  long long steps = 0;  ///< explicit stages: time steps, their dt and energy balance error
  double dt = 0, energy_error = 0;
  long long newton_iterations = -1, cutbacks = 0;  ///< J2 implicit stages (Newton)
  std::vector<std::vector<double>> residuals;      ///< per converged load step (Newton)
};

}  // namespace

void check_shell_setup(const Model& model) {
  check_shell_setup(model, FlatShellOperator(model));
}

void check_shell_setup(const Model& model, const FlatShellOperator& op) {
  for (const auto& stage : model.scene.stages) {
    ShellConstraints(model, op, shell_supports_at(model.scene, stage.name, stage.end_time));
    if (stage.driver == "explicit") op.lumped_mass();  // a mass <= 0 stops the check as the run
  }
}

RunOutcome run_shell_stages(const CommPtr& comm, const Model& model, const std::string& path,
                            double setup_seconds) {
  const auto started = std::chrono::steady_clock::now();
  const auto& scene = model.scene;
  if (!model.mesh.surface.empty())
    Log::info(surface_chart_summary(model.mesh, static_cast<bool>(scene.surface_chart)));
  const FlatShellOperator op(model);
  const auto& fields = scene.output.fields;
  const auto wants = [&](const char* f) {
    return std::find(fields.begin(), fields.end(), f) != fields.end();
  };
  const bool with_stress = wants("stress"), with_resultants = wants("resultants"),
             with_volume = wants("nodal_volume"), with_rank = wants("owner_rank"),
             with_plastic = wants("plastic_strain"), with_thickness = wants("thickness");
  OutputLayout layout;
  for (const char* base : {"displacement_", "rotation_"})
    for (const char* axis : {"x", "y", "z"})
      if (std::string(base) == "displacement_" || std::string(axis) != "z")
        layout.nodal.push_back(std::string(base) + axis);
  const char* const resultant_names[shell_strains] = {
      "membrane_force_xx", "membrane_force_yy", "membrane_force_xy", "moment_xx",
      "moment_yy",         "moment_xy",         "shear_force_xz",    "shear_force_yz"};
  if (with_stress)
    for (const char* side : {"top", "middle", "bottom"})
      for (const char* c : {"xx", "yy", "xy"})
        layout.nodal.push_back(std::string("stress_") + side + "_" + c);
  if (with_resultants)
    for (const char* n : resultant_names) layout.nodal.push_back(n);
  if (with_plastic) layout.nodal.push_back("plastic_strain");
  if (with_thickness) layout.nodal.push_back("thickness");
  if (with_volume) layout.nodal.push_back("nodal_volume");
  if (with_rank) layout.nodal.push_back("owner_rank");
  for (const char* g : {"strain_energy", "kinetic_energy", "external_work"})
    layout.global.push_back(g);
  for (const auto& probe : scene.probes)
    for (const char* n : probe_names) layout.global.push_back("probe_" + probe.name + "_" + n);
  // The supports' forces on the shell, from the Lagrange multipliers of explicit stages (0 in
  // implicit ones, whose collocation rows carry no multipliers): per condition, the components
  // it holds. Only a scene with an explicit stage has these columns.
  const char* const force_names[nd] = {"force_x", "force_y", "force_z", "moment_x", "moment_y"};
  std::vector<std::pair<std::size_t, std::size_t>> support_columns;  // (condition, component)
  const bool any_explicit = std::any_of(scene.stages.begin(), scene.stages.end(),
                                        [](const StageSpec& s) { return s.driver == "explicit"; });
  for (std::size_t i = 0; any_explicit && i < scene.boundary_conditions.size(); ++i) {
    const auto& bc = scene.boundary_conditions[i];
    for (std::size_t c = 0; c < nd; ++c)
      if (c < 3 ? static_cast<bool>(bc.components[c]) : static_cast<bool>(bc.rotations[c - 3])) {
        support_columns.emplace_back(i, c);
        layout.global.push_back("support_" + bc.name + "_" + force_names[c]);
      }
  }
  // The contact force on each rigid body (explicit stages with contacts; 0 otherwise), after the
  // supports' forces in the stage's force list.
  const bool with_bodies = !scene.contacts.empty();
  for (const char* what : {"_F", "_v"})  // the force on each body, then its velocity
    for (std::size_t b = 0; with_bodies && b < scene.rigid_bodies.size(); ++b)
      for (const char* axis : {"x", "y", "z"})
        layout.global.push_back("rb_" + scene.rigid_bodies[b].name + what + axis);
  // Per condition, its place among those active in the stage being run (-1: not active there):
  // the stage's support forces come 5 per active condition, in the scene's order.
  std::vector<int> place_in_stage(scene.boundary_conditions.size(), -1);
  // curved references: the results show the curved surface (a 3D mesh of the mapped nodes)
  const auto shown = op.curved() ? shell_reference_mesh(model) : BackgroundMesh{};
  run_collectively(comm, [&] { check_shell_setup(model, op); });  // no output before its errors
  ResultsOutput output(comm, path, op.curved() ? shown : model.mesh, model.maps.owned_nodes, layout,
                       scene.title.empty() ? scene.name : scene.title, {},
                       scene.output.per_rank_files);
  const auto volume = lumped_nodal_volumes(model.mesh);
  std::vector<std::vector<double>> history;
  FlatShellOperator::Vector d(op.maps().owned_dofs), v(op.maps().owned_dofs);
  RunOutcome outcome;
  // kinetic energy and the external work of the explicit stage so far (0 in static stages)
  auto record = [&](double time, double kinetic, double external_work,
                    const std::vector<double>& forces) {
    const auto values = op.physical_values(d);
    // (J2 parts' probes read the points' resultants too)
    const bool plastic_probes = (op.plastic() || op.finite_rotations()) && !scene.probes.empty();
    std::vector<double> resultants;
    if (with_resultants || plastic_probes) resultants = op.resultants(d);
    const auto stresses = with_stress ? op.surface_stresses(d) : std::vector<double>{};
    // the largest effective plastic strain through the thickness (0 for elastic parts)
    const auto plastic = with_plastic ? op.plastic_strain() : std::vector<double>{};
    const auto thickness = with_thickness ? op.thickness(d) : std::vector<double>{};
    const auto& owned = model.partition.owned;
    Tpetra::MultiVector<> nodal(model.maps.owned_nodes, layout.nodal.size());
    {
      auto out = nodal.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t i = 0; i < owned.size(); ++i) {
        for (std::size_t c = 0; c < nd; ++c) out(i, c) = values[i * nd + c];
        std::size_t column = nd;
        const double* r = resultants.empty() ? nullptr : &resultants[i * shell_strains];
        if (with_stress)
          for (std::size_t c = 0; c < 9; ++c) out(i, column++) = stresses[i * 9 + c];
        if (with_resultants)
          for (std::size_t c = 0; c < shell_strains; ++c) out(i, column++) = r[c];
        if (with_plastic) out(i, column++) = plastic[i];
        if (with_thickness) out(i, column++) = thickness[i];
        if (with_volume) out(i, column++) = volume[static_cast<std::size_t>(owned[i])];
        if (with_rank) out(i, column++) = model.partition.rank;
      }
    }
    double energy = 0, local = op.strain_energy(d);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &local, &energy);
    std::vector<double> global = {energy, kinetic, external_work};
    for (double p : probe_values(model, d, op, resultants)) global.push_back(p);
    for (const auto& [i, c] : support_columns) {
      const int k = place_in_stage[i];
      global.push_back(k >= 0 && !forces.empty() ? forces[static_cast<std::size_t>(k) * nd + c]
                                                 : 0.0);
    }
    const auto active = static_cast<std::size_t>(
        std::count_if(place_in_stage.begin(), place_in_stage.end(), [](int k) { return k >= 0; }));
    for (std::size_t b = 0; with_bodies && b < 2 * scene.rigid_bodies.size(); ++b)
      for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t at = active * nd + 3 * b + k;
        global.push_back(at < forces.size() ? forces[at] : 0.0);
      }
    output.write(time, nodal, global);
    history.push_back(global);
    history.back().insert(history.back().begin(), time);
    ++outcome.records;
  };
  std::vector<StageResult> results;
  // max |w^h| over the particles at the end of a stage (collective)
  const auto largest_deflection = [&](const std::string& stage) {
    double w = 0, all = 0;
    const auto values = op.physical_values(d);
    for (std::size_t i = shell_w; i < values.size(); i += nd) {
      if (!std::isfinite(values[i]))
        throw NumericalError("shell stage '" + stage + "': the solution is not finite");
      w = std::max(w, std::abs(values[i]));
    }
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &w, &all);
    return all;
  };
  try {
    record(0.0, 0.0, 0.0, {});
    double start = 0.0;
    for (const auto& stage : scene.stages) {
      const auto begun = std::chrono::steady_clock::now();
      StageResult r;
      r.name = stage.name;
      r.time = stage.end_time;
      r.dofs = static_cast<long long>(op.maps().owned_dofs->getGlobalNumElements());
      for (std::size_t i = 0, k = 0; i < scene.boundary_conditions.size(); ++i)
        place_in_stage[i] =
            scene.boundary_conditions[i].stages.includes(stage.name) ? static_cast<int>(k++) : -1;
      // the stage's time, energy and deflection at its last record, into the report
      const auto finish = [&] {
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
        r.strain_energy = history.back()[1];
        r.largest_deflection = largest_deflection(stage.name);
        results.push_back(r);
        start = stage.end_time;
      };
      if (stage.driver == "explicit") {
        const auto summary = run_shell_explicit_stage(model, op, stage, start, d, v, record);
        r.steps = summary.steps;
        r.dt = summary.dt;
        r.energy_error = summary.energy_error;
        finish();
        continue;
      }
      if (op.plastic() || op.finite_rotations()) {
        const auto summary =
            run_shell_implicit_stage(model, op, stage, start, scene.stages.front().end_time, d,
                                     [&](double time) { record(time, 0.0, 0.0, {}); });
        r.steps = summary.steps;
        r.newton_iterations = summary.newton_iterations;
        r.cutbacks = summary.cutbacks;
        r.residuals = summary.residuals;
        v.putScalar(0.0);  // a static solution, at rest
        Log::info("stage '" + stage.name + "' done: " + std::to_string(summary.steps) + " steps, " +
                  std::to_string(summary.cutbacks) + " cutbacks, " +
                  std::to_string(summary.newton_iterations) + " Newton iterations (shells, " +
                  summary.linear_solver + ")");
        finish();
        continue;
      }
      const ShellConstraints constraints(model, op, shell_supports_at(scene, stage.name, r.time));
      const auto K = op.stiffness(constraints);
      FlatShellOperator::Vector f(op.maps().owned_dofs);
      op.add_pressure(shell_pressure_at(model, stage.name, r.time), f);
      ShellLineAndPointLoads(model, op, stage.name).add(r.time, 1.0, f);
      constraints.set_values(f);
      const auto lu = make_direct_preconditioner(Teuchos::ParameterList());
      lu->set_map(op.maps().owned_dofs);
      lu->compute(K);
      lu->apply(f, d, Teuchos::NO_TRANS, 1.0, 0.0);
      r.largest_deflection = largest_deflection(stage.name);
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
      v.putScalar(0.0);  // a static solution, at rest
      record(r.time, 0.0, 0.0, {});
      r.strain_energy = history.back()[1];
      start = stage.end_time;
      std::ostringstream o;
      o << "stage '" << stage.name << "' (shells, linear static): " << r.dofs
        << " dofs, direct (MUMPS LU), strain energy " << r.strain_energy << ", largest |w| "
        << r.largest_deflection << ", " << r.seconds << " s";
      Log::info(o.str());
      results.push_back(r);
    }
  } catch (...) {
    // As the solid stages: meet, then a numerical failure keeps the records so far in the .part
    // file; any other leaves nothing (bad input writes nothing).
    if (meet_with_current_failure().code == static_cast<int>(ExitCode::numerical))
      output.close_partial();
    throw;
  }
  output.close();
  const auto& names = layout.global;
  for (std::size_t k = 1; k < names.size(); ++k) {
    std::ostringstream o;
    o.precision(10);
    o << names[k] << " = " << history.back()[k + 1];
    Log::info(o.str());
  }
  if (comm->getRank() == 0) {
    if (!scene.output.history.empty()) {
      const auto file = (std::filesystem::path(path).parent_path() / scene.output.history).string();
      write_then_rename(file, [&](std::ostream& csv) {
        csv << "time";
        for (const auto& n : names) csv << "," << n;
        csv << "\n" << std::setprecision(17);
        for (const auto& row : history) {
          for (std::size_t k = 0; k < row.size(); ++k) csv << (k ? "," : "") << row[k];
          csv << "\n";
        }
      });
    }
    write_then_rename(path + ".report.json", [&](std::ostream& report) {
      report
          << std::setprecision(17) << "{\n  \"scene\": \"" << scene.file << "\",\n"
          << "  \"results\": \"" << path
          << "\",\n  \"formulation\": \"flat Reissner-Mindlin shells\",\n"
          << "  \"seconds\": "
          << setup_seconds +
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()
          << ",\n  \"shell_stages\": [";
      for (std::size_t s = 0; s < results.size(); ++s) {
        report << (s ? "," : "") << "\n    {\"name\": \"" << results[s].name
               << "\", \"time\": " << results[s].time << ", \"dofs\": " << results[s].dofs
               << ", \"seconds\": " << results[s].seconds
               << ", \"strain_energy\": " << results[s].strain_energy
               << ", \"largest_deflection\": " << results[s].largest_deflection;
        if (results[s].newton_iterations >= 0) {
          report << ", \"steps\": " << results[s].steps
                 << ", \"newton_iterations\": " << results[s].newton_iterations
                 << ", \"cutbacks\": " << results[s].cutbacks << ", \"newton_residuals\": [";
          for (std::size_t k = 0; k < results[s].residuals.size(); ++k) {
            report << (k ? ", " : "") << "[";
            for (std::size_t i = 0; i < results[s].residuals[k].size(); ++i)
              report << (i ? ", " : "") << results[s].residuals[k][i];
            report << "]";
          }
          report << "]";
        } else if (results[s].steps > 0) {
          report << ", \"steps\": " << results[s].steps << ", \"dt\": " << results[s].dt
                 << ", \"energy_balance_error\": " << results[s].energy_error;
        }
        report << "}";
      }
      report << "\n  ],\n  \"probes\": {";
      for (std::size_t k = 1; k < names.size(); ++k)
        report << (k > 1 ? "," : "") << "\n    \"" << names[k] << "\": " << history.back()[k + 1];
      report << "\n  }\n}\n";
    });
  }
  Log::info("run report: " + path + ".report.json");
  return outcome;
}

}  // namespace efg
