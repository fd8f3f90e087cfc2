// What a shell stage reads of the scene at a time: its supports (the boundary conditions active
// in the stage, their curves' factors at that time) and its shell_pressure loads.
#pragma once

#include <string>
#include <vector>

#include "model/Model.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellConstraints.hpp"

namespace efg {

/// The displacement and rotation conditions active in `stage`, valued at `time`; a condition
/// without a curve is scaled by `ramp` (implicit load steps: the solids' linear ramp over the
/// first stage, model/Curves.hpp curve_factor).
std::vector<ShellSupport> shell_supports_at(const Scene& scene, const std::string& stage,
                                            double time, double ramp = 1.0);

/// Whether the conditions active in `stage` can prescribe different values at different times
/// (a curve, or an expression of t): explicit stages then re-evaluate them every step.
bool shell_supports_move(const Scene& scene, const std::string& stage);

/// The shell_pressure loads active in `stage`, summed, at `time` (a load without a curve at
/// `ramp` times its value).
FlatShellOperator::Pressure shell_pressure_at(const Model& model, const std::string& stage,
                                              double time, double ramp = 1.0);

}  // namespace efg
