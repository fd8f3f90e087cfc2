// The one material dispatch of the solid kernels (SolidKernels.hpp): per integration point q,
// P (and A = dP/dH, and the strain energy) from the part's law. Elastic laws are a function of
// H alone (physics::stress); J2 plasticity reads the committed history of q and writes the
// trial history (physics::j2_update; its tangent by forward AD, MaterialTangent.hpp); the
// crushable foam likewise (physics::foam_update, its history row laid out so that the energy and
// erosion columns are J2's). An elastic part pays one predictable branch per point (bench/:
// efg_bench_explicit).
#pragma once

#include <type_traits>

#include "core/DeviceArrays.hpp"
#include "materials/SolidMaterial.hpp"
#include "operators/MaterialTangent.hpp"

namespace efg {

struct PointMaterial {
  physics::SolidMaterial elastic;
  bool plastic = false;
  physics::J2Parameters j2;
  DeviceView<double**> committed, trial;  ///< points x j2_state::count (plastic parts)
  double step_time = 0.0;                 ///< time increment of the step (rate term)
  /// Graded elastic parts: E(x_q)/E_ref scales lambda and mu at q (empty: uniform part).
  DeviceView<double*> modulus_scale;
  bool graded = false;
  bool foam = false;  ///< with plastic: the crushable foam law (foam_params) instead of J2
  physics::CrushableFoamParameters foam_params;
  bool low_density = false;  ///< with plastic: the low-density foam law (ldfoam_params)
  physics::LowDensityFoamParameters ldfoam_params;
};

/// The elastic law at q: the part's, scaled at a graded point.
KOKKOS_INLINE_FUNCTION physics::SolidMaterial elastic_at(const PointMaterial& m, int q) {
  return m.graded ? physics::with_moduli_scaled(m.elastic, m.modulus_scale(q)) : m.elastic;
}

namespace point_material_detail {
// A point's history is one row of a row-major view: its doubles are contiguous, so the row can
// be handed to the physics kernels as a fixed-size array.
static_assert(std::is_same_v<DeviceView<double**>::array_layout, Kokkos::LayoutRight>,
              "history rows must be contiguous");
using State = double[physics::j2_state::count];
// The foam's row is read through the same type and by the same columns (SolidKernels).
static_assert(physics::foam_state::count == physics::j2_state::count &&
                  physics::foam_state::dissipation == physics::j2_state::dissipation &&
                  physics::foam_state::elastic_energy == physics::j2_state::elastic_energy &&
                  physics::foam_state::eroded == physics::j2_state::eroded &&
                  physics::foam_state::crush == physics::j2_state::alpha,
              "the foam's history row must share J2's energy, erosion and output columns");
static_assert(physics::ldfoam_state::count == physics::j2_state::count &&
                  physics::ldfoam_state::dissipation == physics::j2_state::dissipation &&
                  physics::ldfoam_state::elastic_energy == physics::j2_state::elastic_energy &&
                  physics::ldfoam_state::eroded == physics::j2_state::eroded &&
                  physics::ldfoam_state::crush == physics::j2_state::alpha,
              "the low-density foam's history row must share J2's columns");
KOKKOS_INLINE_FUNCTION const State& row(const DeviceView<double**>& v, int q) {
  return *reinterpret_cast<const State*>(&v(q, 0));
}
KOKKOS_INLINE_FUNCTION State& mutable_row(const DeviceView<double**>& v, int q) {
  return *reinterpret_cast<State*>(&v(q, 0));
}
}  // namespace point_material_detail

/// P at point q; A when given. False when the point is inverted (det F <= 0).
template <int Dim>
KOKKOS_INLINE_FUNCTION bool point_stress(const PointMaterial& m, int q, const double (&H)[Dim][Dim],
                                         double (&P)[Dim][Dim],
                                         double (*A)[Dim][Dim][Dim] = nullptr) {
  if (!m.plastic) return physics::stress<Dim>(elastic_at(m, q), H, P, A);
  using namespace point_material_detail;
  double cauchy[3][3];
  if (m.low_density && A)
    return ldfoam_stress_and_bound_tangent<Dim>(m.ldfoam_params, H, row(m.committed, q), P,
                                                *reinterpret_cast<double(*)[Dim][Dim][Dim][Dim]>(A),
                                                mutable_row(m.trial, q), cauchy);
  if (m.low_density)
    return physics::ldfoam_update<Dim>(m.ldfoam_params, H, row(m.committed, q), P,
                                       mutable_row(m.trial, q), cauchy);
  if (m.foam && A)
    return foam_stress_and_elastic_tangent<Dim>(m.foam_params, H, row(m.committed, q), P,
                                                *reinterpret_cast<double(*)[Dim][Dim][Dim][Dim]>(A),
                                                mutable_row(m.trial, q), cauchy);
  if (m.foam)
    return physics::foam_update<Dim>(m.foam_params, H, row(m.committed, q), P,
                                     mutable_row(m.trial, q), cauchy);
  if (A)
    return j2_stress_and_tangent<Dim>(m.j2, H, row(m.committed, q), m.step_time, P,
                                      *reinterpret_cast<double(*)[Dim][Dim][Dim][Dim]>(A),
                                      mutable_row(m.trial, q), cauchy);
  return physics::j2_update<double, Dim>(m.j2, H, row(m.committed, q), m.step_time, P,
                                         mutable_row(m.trial, q), cauchy);
}

/// Internal energy per unit reference volume at q: the strain energy of an elastic law; stored
/// plus dissipated energy of J2 at the end of the step from the committed state (0 when
/// inverted). Writes nothing.
template <int Dim>
KOKKOS_INLINE_FUNCTION double point_energy(const PointMaterial& m, int q,
                                           const double (&H)[Dim][Dim]) {
  if (!m.plastic) return physics::strain_energy<Dim>(elastic_at(m, q), H);
  using namespace point_material_detail;
  double P[Dim][Dim], next[physics::j2_state::count], cauchy[3][3];
  if (m.low_density)
    return physics::ldfoam_update<Dim>(m.ldfoam_params, H, row(m.committed, q), P, next, cauchy)
               ? next[physics::ldfoam_state::elastic_energy] +
                     next[physics::ldfoam_state::dissipation]
               : 0.0;
  if (m.foam)
    return physics::foam_update<Dim>(m.foam_params, H, row(m.committed, q), P, next, cauchy)
               ? next[physics::foam_state::elastic_energy] + next[physics::foam_state::dissipation]
               : 0.0;
  if (!physics::j2_update<double, Dim>(m.j2, H, row(m.committed, q), m.step_time, P, next, cauchy))
    return 0.0;
  return next[physics::j2_state::elastic_energy] + next[physics::j2_state::dissipation];
}

/// Cauchy stress (3 x 3) at q for output, from the committed state.
template <int Dim>
KOKKOS_INLINE_FUNCTION void point_cauchy_stress(const PointMaterial& m, int q,
                                                const double (&H)[Dim][Dim],
                                                double (&sigma)[3][3]) {
  if (!m.plastic) return physics::cauchy_stress<Dim>(elastic_at(m, q), H, sigma);
  using namespace point_material_detail;
  double P[Dim][Dim], next[physics::j2_state::count];
  const bool ok =
      m.low_density
          ? physics::ldfoam_update<Dim>(m.ldfoam_params, H, row(m.committed, q), P, next, sigma)
      : m.foam ? physics::foam_update<Dim>(m.foam_params, H, row(m.committed, q), P, next, sigma)
               : physics::j2_update<double, Dim>(m.j2, H, row(m.committed, q), m.step_time, P, next,
                                                 sigma);
  if (!ok)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sigma[i][j] = 0.0;
}

}  // namespace efg
