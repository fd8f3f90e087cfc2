// An explicit stage of flat shells (linear, small rotations): central differences on the
// generalized dofs with the lumped mass and scaled rotary inertia of FlatShellOperator, the
// internal force K d assembled point by point (no matrix), the supports held by forward-increment
// Lagrange multipliers (shells/ShellMultipliers) and the stable step from the largest frequency
// of M^-1 K (drivers/StableTimeStep, Anasazi, matrix-free). The state (d, v) carries over from
// and to the neighbouring stages: an implicit static stage hands its solution over at rest.
#pragma once

#include <functional>
#include <vector>

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

/// At a record: the kinetic energy, the work of the loads and moving supports since the stage
/// began, and the forces: of every support on the shell (5 components per condition active in the
/// stage, in the scene's order; ShellMultipliers::support_forces and the nitsche and penalty
/// supports' boundary terms), then, with contacts, the contact force on every scene rigid body
/// and its velocity (3 components each; contact/ShellRigidContact).
using ShellRecord = std::function<void(double time, double kinetic_energy, double external_work,
                                       const std::vector<double>& support_forces)>;

/// Runs `stage` from `start` to its end_time, d and v (owned dofs) in place; calls `record` at
/// every output_interval (and at the end). Supports follow their values and curves at every
/// step. Throws NumericalError naming the step, the time and the particle when the
/// displacement stops being finite.
ShellExplicitSummary run_shell_explicit_stage(const Model& model, const FlatShellOperator& op,
                                              const StageSpec& stage, double start,
                                              FlatShellOperator::Vector& d,
                                              FlatShellOperator::Vector& v,
                                              const ShellRecord& record);

}  // namespace efg
