// The constitutive law of each part, as the physics kernels take it: the elastic laws
// (physics/materials/SolidMaterial.hpp) or J2 plasticity (physics/materials/J2Plasticity.hpp)
// with its hardening curve and history state. Read from the scene's material and part.
#pragma once

#include "materials/CrushableFoam.hpp"
#include "materials/J2Plasticity.hpp"
#include "materials/LowDensityFoam.hpp"
#include "materials/SolidMaterial.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Doubles of history per integration point of the law that keeps the most (J2): the columns of
/// the material_state output field (restarts read them back).
constexpr int kLargestStateCount = physics::j2_state::count;

struct MaterialLaw {
  /// The elastic law; for a path-dependent part its elastic constants (the stable time step,
  /// penalty scales and messages read them).
  physics::SolidMaterial elastic;
  bool plastic = false;  ///< J2 plasticity with history state
  /// formulation mixed_up: `elastic` is the deviatoric part of the law (lambda = -2 mu / 3, so
  /// that lambda tr(eps) I + 2 mu eps = 2 mu dev eps with eps_33 = 0 in plane strain) and the
  /// volumetric part, kappa times the cell's dilatation, is the cell pressure's
  /// (operators/MixedPressure). 0 for displacement parts.
  double bulk_modulus = 0.0;
  bool mixed() const { return bulk_modulus > 0; }
  physics::J2Parameters j2;
  /// The crushable foam (model crushable_foam): plastic is true too (a history row of
  /// foam_state::count doubles, the same count as J2's), foam_params its law.
  bool foam = false;
  physics::CrushableFoamParameters foam_params;
  /// The low-density foam (model low_density_foam): plastic is true too (a history row of
  /// ldfoam_state::count doubles, J2's count), ldfoam_params its law.
  bool low_density = false;
  physics::LowDensityFoamParameters ldfoam_params;
  /// Doubles of history per integration point (0: the law keeps none).
  int state_count() const { return plastic ? physics::j2_state::count : 0; }
  /// The history of a point that has not deformed yet (plastic laws; the foams keep as many
  /// doubles as J2).
  void initial_state(double (&state)[physics::j2_state::count]) const {
    static_assert(physics::foam_state::count == physics::j2_state::count &&
                      physics::ldfoam_state::count == physics::j2_state::count,
                  "one history row size for every plastic law");
    if (low_density)
      physics::ldfoam_initial_state(state);
    else if (foam)
      physics::foam_initial_state(state);
    else
      physics::j2_initial_state(j2, state);
  }
};

/// Material constants of a part for the elastic kernels (plane stress reduces lambda).
physics::SolidMaterial solid_material(const MaterialSpec& material, const PartSpec& part,
                                      int dimension);

/// The law of `part` (its material and formulation) in a model of `dimension`.
MaterialLaw material_law(const Scene& scene, const PartSpec& part, int dimension);

}  // namespace efg
