// The consistent tangent A = dP/dH of the J2 update (physics/materials/J2Plasticity.hpp) by
// forward AD: the update runs once on Sacado SFad<double, Dim * Dim> numbers seeded on the
// components of H, so A is the derivative of the algorithm itself (the algorithmic tangent of
// Simo & Taylor, CMAME 48 (1985) 101-118), at round-off accuracy and with no hand-derived
// fourth-order tensors to keep in step with the law.
#pragma once

#include <Sacado.hpp>

#include "materials/CrushableFoam.hpp"
#include "materials/J2Plasticity.hpp"
#include "materials/LowDensityFoam.hpp"

namespace efg {

/// P, A[i][j][k][l] = dP_ij / dH_kl, the new state and the Cauchy stress of one J2 step (see
/// physics::j2_update; false when det F <= 0).
template <int Dim>
KOKKOS_INLINE_FUNCTION bool j2_stress_and_tangent(
    const physics::J2Parameters& p, const double (&H)[Dim][Dim],
    const double (&old_state)[physics::j2_state::count], double dt, double (&P)[Dim][Dim],
    double (&A)[Dim][Dim][Dim][Dim], double (&new_state)[physics::j2_state::count],
    double (&cauchy)[3][3]) {
  using Fad = Sacado::Fad::SFad<double, Dim * Dim>;
  Fad h[Dim][Dim], stress[Dim][Dim];
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) h[k][l] = Fad(Dim * Dim, k * Dim + l, H[k][l]);
  if (!physics::j2_update<Fad, Dim>(p, h, old_state, dt, stress, new_state, cauchy)) return false;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      P[i][j] = stress[i][j].val();
      for (int k = 0; k < Dim; ++k)
        for (int l = 0; l < Dim; ++l) A[i][j][k][l] = stress[i][j].fastAccessDx(k * Dim + l);
    }
  return true;
}

/// The crushable foam's P, new state and Cauchy stress (physics::foam_update) with A = the
/// derivative of its elastic predictor from the committed state (forward AD): the unloading
/// stiffness, which bounds the plastic one from above (the box return only lowers stresses at
/// fixed J), so the explicit stable-step bound built from it is safe. It is not the consistent
/// tangent: implicit stages refuse the law (scene/PlasticityInput).
template <int Dim>
KOKKOS_INLINE_FUNCTION bool foam_stress_and_elastic_tangent(
    const physics::CrushableFoamParameters& p, const double (&H)[Dim][Dim],
    const double (&old_state)[physics::foam_state::count], double (&P)[Dim][Dim],
    double (&A)[Dim][Dim][Dim][Dim], double (&new_state)[physics::foam_state::count],
    double (&cauchy)[3][3]) {
  if (!physics::foam_update<Dim>(p, H, old_state, P, new_state, cauchy)) return false;
  using Fad = Sacado::Fad::SFad<double, Dim * Dim>;
  Fad h[Dim][Dim], stress[Dim][Dim];
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) h[k][l] = Fad(Dim * Dim, k * Dim + l, H[k][l]);
  if (!physics::foam_elastic_predictor<Fad, Dim>(p, h, old_state, stress)) return false;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j)
      for (int k = 0; k < Dim; ++k)
        for (int l = 0; l < Dim; ++l) A[i][j][k][l] = stress[i][j].fastAccessDx(k * Dim + l);
  return true;
}

/// The low-density foam's P, new state and Cauchy stress (physics::ldfoam_update) with A = the
/// derivative of its bound law P = K (F - R) (forward AD): its largest eigenvalue is K, the bound
/// of every direction's slope (LowDensityFoam.hpp), so the explicit stable step built from it is
/// safe. Not the consistent tangent: implicit stages refuse the law (scene/PlasticityInput).
template <int Dim>
KOKKOS_INLINE_FUNCTION bool ldfoam_stress_and_bound_tangent(
    const physics::LowDensityFoamParameters& p, const double (&H)[Dim][Dim],
    const double (&old_state)[physics::ldfoam_state::count], double (&P)[Dim][Dim],
    double (&A)[Dim][Dim][Dim][Dim], double (&new_state)[physics::ldfoam_state::count],
    double (&cauchy)[3][3]) {
  if (!physics::ldfoam_update<Dim>(p, H, old_state, P, new_state, cauchy)) return false;
  using Fad = Sacado::Fad::SFad<double, Dim * Dim>;
  Fad h[Dim][Dim], stress[Dim][Dim];
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) h[k][l] = Fad(Dim * Dim, k * Dim + l, H[k][l]);
  if (!physics::ldfoam_bound_stress<Fad, Dim>(p, h, stress)) return false;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j)
      for (int k = 0; k < Dim; ++k)
        for (int l = 0; l < Dim; ++l) A[i][j][k][l] = stress[i][j].fastAccessDx(k * Dim + l);
  return true;
}

}  // namespace efg
