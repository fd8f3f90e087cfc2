// The explicit driver's vector passes around its one internal force, each fused where the
// driver made several (issue 56, item 6: on a 1.1e5-particle block the driver's step cost
// 1.4-1.6x the kernel's, the difference vector passes over the owned dofs, not the force). Each
// gives the bits of the passes it replaces: the same operations in the same order per entry,
// and sums in reproducible_dot's blocks (parallel/ReproducibleSum.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "operators/SolidOperator.hpp"

namespace efg {

/// The step's predictor in one pass: v_half = v + dt/2 a, delta = dt v_half, d = d_start + delta.
void predict(double dt, const Vector& d_start, const Vector& v, const Vector& a, Vector& v_half,
             Vector& delta, Vector& d);
/// delta and d again on `rows` alone, after their v_half was overwritten there (prescribed
/// motions: PrescribedMotion::constrain_velocity).
void predict_rows(const std::vector<int>& rows, double dt, const Vector& d_start,
                  const Vector& v_half, Vector& delta, Vector& d);

/// a = M^-1 (f_ext - f_int [+ f_wall] [- f_viscous]) in one pass (the terms in that order: the
/// separate updates' rounding). Null `f_wall` or `f_viscous`: no such term. With `v_end` also
/// v_end = v_half + half_dt a (the step's corrector) in the same pass.
void acceleration_from_forces(const Vector& f_ext, const Vector& f_int, const Vector* f_wall,
                              const Vector* f_viscous, const Vector& inverse_mass, Vector& a,
                              const Vector* v_half = nullptr, double half_dt = 0,
                              Vector* v_end = nullptr);

/// What the end of a step needs summed over the owned dofs (collective).
struct StepSums {
  static constexpr std::size_t max_forces = 8;
  /// forces[i] . delta, each bit for bit reproducible_dot(forces[i], delta).
  std::array<double, max_forces> work{};
  /// Every displacement and velocity finite on every rank (the driver's NaN guard).
  bool finite = true;
};

/// The energy account's trapezoid dots and the NaN guard in one pass and one reduction over
/// ranks. Apart, six dots read delta six times, each one dependent chain of adds after the
/// other, and the guard read d and v again: 3.7 ms of a 33 ms step at 1.1e5 particles. Here a
/// block's chains run side by side and every vector is read once.
StepSums step_sums(const std::vector<const Vector*>& forces, const Vector& delta, const Vector& d,
                   const Vector& v);

}  // namespace efg
