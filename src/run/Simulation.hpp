// One run of a scene after its model is built: the results file, the state carried from stage
// to stage, and the stage drivers. A scene builds only what it needs: the stiffness graph and
// solvers exist only when a stage is implicit.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/Model.hpp"
#include "verification/ErrorNorms.hpp"

namespace efg {

struct RunOutcome {
  int records = 0;
  std::optional<ErrorNorms> errors;        ///< when the scene names an exact solution
  std::vector<std::string> failed_checks;  ///< reference values missed (descriptions)
};

/// Runs every stage of the model, writes the results to `path` and the run report to
/// `path`.report.json; `setup_seconds` is the time spent before (scene, mesh, discretization).
RunOutcome run_stages(const CommPtr& comm, const Model& model, const std::string& path,
                      double setup_seconds = 0);

}  // namespace efg
