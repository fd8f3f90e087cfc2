// The run of a scene whose parts are shells (src/shells): each implicit stage is one linear
// static solve at its end time (loads and prescribed values at that time, a load without a
// curve at full value), each explicit stage a run of central differences from the state the
// previous stage left (run/ShellExplicitStage), the results written to Exodus (displacement x, y, z and rotation x, y
// of every particle: the physical values u^h(X_J), not the generalized dofs) and the probes'
// values to the log, the history CSV and the run report.
#pragma once

#include <string>

#include "model/Model.hpp"
#include "run/Simulation.hpp"

namespace efg {

class FlatShellOperator;

RunOutcome run_shell_stages(const CommPtr& comm, const Model& model, const std::string& path,
                            double setup_seconds = 0);

/// What `efg check` builds of a shell scene: the operator and every stage's constraints (edge
/// points, collocation rows), so that their errors show before a run (which checks the same
/// with its own operator before it opens any output).
void check_shell_setup(const Model& model);
void check_shell_setup(const Model& model, const FlatShellOperator& op);

}  // namespace efg
