// The run report, <results>.report.json beside the Exodus file: what ran, what it cost and how
// wrong it is where the answer is known (docs/report.md has the schema).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "drivers/ExplicitDriver.hpp"
#include "drivers/ImplicitDriver.hpp"
#include "drivers/RunState.hpp"
#include "operators/ModelOperators.hpp"
#include "run/RunSummary.hpp"
#include "verification/ErrorNorms.hpp"

namespace efg {

/// A scalar result checked against the scene's verification.reference_values.
struct ReferenceCheck {
  std::string name, quantity;
  double value = 0, reference = 0, tolerance = 0;
  bool passed() const { return std::abs(value - reference) <= tolerance * std::abs(reference); }
};

/// Evaluates the reference values at the final state. A quantity is a global variable of the
/// results (e.g. R_clamp_y, kinetic_energy) or "<displacement|velocity>_<x|y|z>@<node set>"
/// (the set's mean physical value). Collective. Throws InputError for an unknown quantity.
std::vector<ReferenceCheck> reference_checks(const ModelOperators& ops, const RunState& state,
                                             const std::vector<std::string>& global_names,
                                             const std::vector<double>& global_values);

/// What an implicit stage's solvers did, for the report.
struct ImplicitStageReport {
  std::string stage;
  StageSummary summary;
};

/// What an explicit stage's steps did, for the report (its quasi-static indicator included).
struct ExplicitStageReport {
  std::string stage;
  ExplicitSummary summary;
};

/// Probe name -> value (probe_<name>_<quantity>, as the history columns).
using ProbeValues = std::vector<std::pair<std::string, double>>;

/// Writes the report on rank 0 (collective: timers and memory are reduced over ranks).
void write_run_report(const CommPtr& comm, const Model& model, const std::string& json_path,
                      const std::string& results_path, const RunState& state,
                      const std::optional<ErrorNorms>& errors,
                      const std::vector<ReferenceCheck>& checks, double total_seconds,
                      const std::vector<ImplicitStageReport>& implicit = {},
                      const ProbeValues& probes = {}, const std::vector<MemoryPhase>& memory = {},
                      const std::vector<std::pair<std::string, ProbeValues>>& probes_by_stage = {},
                      const std::vector<std::pair<std::string, ProbeValues>>& angles_by_stage = {},
                      const std::vector<ExplicitStageReport>& explicit_stages = {});

/// The wall-time phases the report lists (Teuchos timer names without the "efg: " prefix).
const std::vector<std::string>& report_phases();

}  // namespace efg
