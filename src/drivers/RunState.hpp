// The state a run carries from stage to stage: generalized displacements, velocities and
// accelerations of the particles (owned dofs), the time, and the energy account of the explicit
// driver. An implicit stage leaves velocities and accelerations at zero.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/RigidBodyState.hpp"
#include "operators/SolidOperator.hpp"

namespace efg {

struct RunState {
  explicit RunState(const Teuchos::RCP<const Map>& owned_dofs)
      : d(owned_dofs), v(owned_dofs), a(owned_dofs) {}

  Vector d, v, a;
  double time = 0;
  double dt = 0;
  // Energy account (explicit): E_kin + E_int = E_0 + W_ext + W_wall when balanced (E_kin with
  // the free rigid bodies', W_wall the work of walls and contacts on particles and free bodies).
  double kinetic = 0, internal = 0, external_work = 0, wall_work = 0, initial_energy = 0;
  /// Work dissipated by the bulk viscosity of mixed u-p cells (explicit): E_kin + E_int + D =
  /// E_0 + W_ext + W_wall.
  double damping_work = 0;
  /// Work dissipated by the stages' mass-proportional damping (drivers/MassDamping).
  double mass_damping_work = 0;
  bool energy_started = false;
  /// The normal force of each rigid wall, then the force of each contact between deformable
  /// parts on its target parts (3 components each).
  std::vector<double> wall_forces;
  /// Rigid bodies (scene order): displacement, velocity and contact force, carried across stages.
  std::vector<RigidBodyState> bodies;
  /// Per scene contact, its particles' initial depths still ignored (initial_penetration:
  /// ignore; PenaltyContact::allowances), carried across stages as the bodies are.
  std::vector<std::vector<double>> contact_allowances;
  /// Per scene contact (explicit stages, rigid bodies): the deepest particle as a fraction of
  /// its spacing since the previous record (contact/PenetrationChecks.hpp); empty otherwise.
  std::vector<double> contact_penetrations;
  /// Linear momentum of the particles (sum M_I v_I, lumped mass) and the free rigid bodies
  /// (explicit stages; the contact pair forces cancel in it).
  std::array<double, 3> momentum{};
  /// Reactions per boundary condition when the driver computes them (explicit: the support
  /// forces of the prescribed motions); otherwise the static residual gives them.
  std::vector<std::array<double, 3>> reactions;
  bool reactions_from_driver = false;

  /// |E_kin + E_int + D - E_0 - W_ext - W_wall| relative to the largest energy involved (D: the
  /// bulk viscosity's and the mass damping's work).
  double balance_error() const {
    const double total = kinetic + internal + damping_work + mass_damping_work - initial_energy -
                         external_work - wall_work;
    const double scale =
        std::max({std::abs(kinetic), std::abs(internal),
                  std::abs(initial_energy) + std::abs(external_work) + std::abs(wall_work)});
    return scale > 0 ? std::abs(total) / scale : 0.0;
  }
};

}  // namespace efg
