// One run of a scene after its model is built: the results file, the state carried from stage
// to stage, and the stage drivers. A scene builds only what it needs: the stiffness graph and
// solvers exist only when a stage is implicit.
#pragma once

#include <string>

#include "run/Model.hpp"

namespace efg {

/// Runs every stage of the model and writes the results to `path`; returns the number of records.
int run_stages(const CommPtr& comm, const Model& model, const std::string& path);

}  // namespace efg
