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
// sec. 6.3): the springs k_K are fixed by the parts, not by dt, so they enter the eigenvalue
// problem of the stable step itself: omega^2 the largest eigenvalue of M^-1 (K + K_c),
// K_c = sum_J k_J,max phi_J phi_J^T I (drivers/ExplicitDriver::extra_stiffness; k_J,max with the
// largest facing area, and isotropic, bound the spring k n n^T along any normal). The mass rule
// adds P = penalty along with its damper (share S = penalty + 4 D sqrt(penalty)), and the
// material springs' dampers c = 2 D sqrt(k m) (lagged velocity) add 2 c dt / m <= 4 D w dt,
// w^2 = max_J k_J,max / m_J, so the step solves
//   omega^2 dt^2 + 4 D w dt - (4 - S) <= 0,
// i.e. 2 / omega sqrt(1 - S / 4) without dampers. A stiffer contact lowers the step. (A bound
// omega_K^2 + w^2 on the eigenvalue, tried first, is no bound: the springs act on overlapping
// shape-function rows, and the foam block's eigenvalue with them, 6203^2, exceeded
// 4352^2 + 3356^2.)
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

/// The positive root of omega2 dt^2 + damper dt - (4 - share) = 0: the stable step of a system
/// whose largest omega^2 is omega2, with a lagged damper adding `damper` dt (4 D w) and the mass
/// rule's share S.
inline double damped_stable_step(double omega2, double damper, double share) {
  const double c = 4.0 - share;
  if (!(omega2 > 0) || !(c > 0)) return 0.0;
  return (-damper + std::sqrt(damper * damper + 4.0 * omega2 * c)) / (2.0 * omega2);
}

}  // namespace efg::contact
