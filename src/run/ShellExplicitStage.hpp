// An explicit stage of flat shells (linear, small rotations): central differences on the
// generalized dofs with the lumped mass and scaled rotary inertia of FlatShellOperator, the
// internal force K d assembled point by point (no matrix), the supports held by forward-increment
// Lagrange multipliers (shells/ShellMultipliers) and the stable step from the largest frequency
// of M^-1 K (drivers/StableTimeStep, Anasazi, matrix-free). The state (d, v) carries over from
// and to the neighbouring stages: an implicit static stage hands its solution over at rest.
#pragma once

#include <functional>

#include "model/Model.hpp"
#include "scene/Scene.hpp"
#include "shells/FlatShellOperator.hpp"

namespace efg {

struct ShellExplicitSummary {
  long long steps = 0;
  double dt = 0, dt_crit = 0, largest_frequency = 0;
  /// |E_kin + E_int - E_kin0 - E_int0 - W_ext| over the largest of those terms, worst record.
  double energy_error = 0;
};

/// Energies at a record: kinetic, and the external work done since the stage began.
using ShellRecord = std::function<void(double time, double kinetic_energy, double external_work)>;

/// Throws InputError when a condition active in the explicit `stage` prescribes a value other
/// than zero at its start or end (held supports only in this version). Run by `efg check` too.
void check_shell_explicit_stage(const Model& model, const FlatShellOperator& op,
                                const StageSpec& stage);

/// Runs `stage` from `start` to its end_time, d and v (owned dofs) in place; calls `record` at
/// every output_interval (and at the end). Throws NumericalError naming the step, the time and
/// the particle when the displacement stops being finite, InputError when a support is not held
/// at zero (prescribed motions of explicit shells are not built yet).
ShellExplicitSummary run_shell_explicit_stage(const Model& model, const FlatShellOperator& op,
                                              const StageSpec& stage, double start,
                                              FlatShellOperator::Vector& d,
                                              FlatShellOperator::Vector& v,
                                              const ShellRecord& record);

}  // namespace efg
