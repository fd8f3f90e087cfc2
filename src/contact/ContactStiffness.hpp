// The explicit contact's normal stiffness per surface particle J against a rigid body (plain
// functions, no Trilinos): the larger of
//   the mass rule      k_m = penalty m_J / dt^2                   (stable for penalty <= 1)
//   the material rule  k_K = scale K A_J^2 / V_J,  V_J = A_J h_J,  i.e.  scale K A_J / h_J
// with K the bulk modulus of J's part, A_J its share of the part's boundary (x thickness in
// 2D) and h_J its boundary spacing (contact/BoundaryShares) - LS-DYNA's segment penalty
// SLSFAC K A^2 / V (LS-DYNA Theory Manual, "Penalty method") with the particle's slab of the
// surface as V. The mass rule alone follows the time step, not the parts: a soft part pressed
// by a heavy tool sank by many spacings. With k_K a pressure p on the surface sinks a particle
// by delta = p A / k_K = p h / (scale K): delta / h = p / (scale K), independent of the mesh.
//
// Stability (central differences, Belytschko, Liu and Moran, "Nonlinear Finite Elements",
// sec. 6.3): the spring adds k / m to a particle's omega^2 and its damper c = 2 D sqrt(k m)
// (lagged velocity) 2 c dt / m to omega^2 dt^2, so dt^2 omega_K^2 + P + 4 D sqrt(P) <= 4 with
// P = k dt^2 / m. With k <= k_K + k_m: P <= w^2 dt^2 + p, w^2 = max_J k_K / m_J, and
// sqrt(P) <= w dt + sqrt(p), so it suffices that
//   (omega_K^2 + w^2) dt^2 + 4 D w dt - (4 - S) <= 0,   S = p + 4 D sqrt(p)
// (S the mass rule's share, contact_stability_share; omega_K^2 + w^2 bounds the largest
// eigenvalue of the sum by Weyl's inequality): dt_crit is that quadratic's positive root, which
// is 2 / omega_K sqrt(1 - S / 4) at w = 0. A stiffer contact lowers the step.
#pragma once

#include <cmath>

namespace efg::contact {

/// The bulk modulus of an elastic law of Young's modulus E and Poisson's ratio nu: E / (3 (1 -
/// 2 nu)); in plane stress the in-plane one, E / (2 (1 - nu)).
inline double bulk_modulus(double E, double nu, bool plane_stress) {
  return plane_stress ? E / (2.0 * (1.0 - nu)) : E / (3.0 * (1.0 - 2.0 * nu));
}

/// The material rule k_K = scale K A / h (0 off the boundary).
inline double material_stiffness(double scale, double K, double area, double spacing) {
  return area > 0 && spacing > 0 ? scale * K * area / spacing : 0.0;
}

/// The stable step with contact springs: the positive root of (omega^2 + w2) dt^2 + 4 D sqrt(w2)
/// dt - (4 - share) = 0 (above); omega the solid's largest frequency, w2 the largest k_K / m,
/// share the mass rule's S, damping D.
inline double contact_stable_step(double omega, double w2, double share, double damping) {
  const double a = omega * omega + w2, b = 4.0 * damping * std::sqrt(w2);
  const double c = 4.0 - share;
  if (!(a > 0) || !(c > 0)) return 0.0;
  return (-b + std::sqrt(b * b + 4.0 * a * c)) / (2.0 * a);
}

}  // namespace efg::contact
