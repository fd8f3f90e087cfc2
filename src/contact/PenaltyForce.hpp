// The explicit penalty force of a particle inside a rigid body (plain functions, no Trilinos),
// shared by the solids' contact (contact/PenaltyContact) and the shells' (ShellRigidContact):
//   slip  s = (x - x_old) - (u - u_old) - dtheta x (x - (c + u)): the particle's motion against
//         the body's surface point over the step (translation, and the turn of a rotating body
//         about its reference point c);
//   F     = max(0, k (-g) - c v_n) n + F_t,  c = 2 damping sqrt(k m),  v_n = s . n / dt,
// F_t the Coulomb return map on s (contact/CoulombFriction.hpp; none without friction).
#pragma once

#include <algorithm>
#include <cmath>

#include "contact/CoulombFriction.hpp"
#include "contact/RigidShape.hpp"

namespace efg::contact {

/// s = (x - x_old) - (u - u_old) - dtheta x (x - (c + u)), the body's displacement u (u_old at
/// the step's start), its turn dtheta over the step, `dim` components (the rest 0).
inline void slip_against_body(const Shape& shape, const double* x, const double* x_old,
                              const double* u, const double* u_old, const double* dtheta, int dim,
                              double* s) {
  double c[3], r[3] = {0, 0, 0};
  reference_point(shape, c);
  for (int k = 0; k < shape.dim; ++k) r[k] = x[k] - (c[k] + u[k]);
  const double turn[3] = {dtheta[1] * r[2] - dtheta[2] * r[1], dtheta[2] * r[0] - dtheta[0] * r[2],
                          dtheta[0] * r[1] - dtheta[1] * r[0]};
  for (int k = 0; k < 3; ++k)
    s[k] = k < dim ? (x[k] - x_old[k]) - (u[k] - u_old[k]) - turn[k] : 0.0;
}

/// The force F (dim components) on a particle of mass m at gap g < 0 with normal n and slip s over
/// dt, penalty stiffness k; with friction the tangential force ft_new from ft_old. Returns the
/// normal force.
inline double penalty_force(const Proximity& near, const double* s, double k, double m,
                            double damping, const Friction& friction, const double* ft_old,
                            double dt, int dim, double* ft_new, double* F) {
  double v_n = 0;
  for (int i = 0; i < dim; ++i) v_n += s[i] * near.normal[i] / dt;
  const double fn = std::max(0.0, -k * near.gap - 2.0 * damping * std::sqrt(k * m) * v_n);
  for (int i = 0; i < dim; ++i) F[i] = fn * near.normal[i];
  if (friction.mu_s > 0 || friction.mu_d > 0) {
    coulomb_return(friction, ft_old, s, near.normal, k, fn, dt, dim, ft_new);
    for (int i = 0; i < dim; ++i) F[i] += ft_new[i];
  }
  return fn;
}

}  // namespace efg::contact
