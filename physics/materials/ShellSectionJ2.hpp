// J2 plasticity through the thickness of a Reissner-Mindlin section (small strain): at each of
// the section's Gauss points z_k the in-plane strain is eps + z_k kappa (Voigt xx, yy, 2 xy),
// the plane-stress J2 law (J2Plasticity.hpp, sigma_zz = 0 solved locally, its own history per
// point) gives the stress, and the resultants are the Gauss sums
//   N = sum_k w_k t/2 sigma(z_k),   M = sum_k w_k t/2 z_k sigma(z_k)
// (the layered integration of explicit shell codes: Hughes & Liu, CMAME 26, 1981; LS-DYNA's
// NIP). The transverse shear stays elastic (k_s G t gamma), as in those codes. With the elastic
// law the sums reproduce A eps and D kappa (two points or more: the stress is linear in z);
// once the section yields the stress has kinks in z and Gauss rules converge slowly: the fully
// plastic moment of n points is sum_k w_k |xi_k| times the exact one (0.945 at n = 5, 0.982 at
// n = 9, 1.005 at n = 12: odd counts fall short, even ones overshoot; docs/shells.md).
#pragma once

#include "materials/J2Plasticity.hpp"
#include "materials/MindlinSection.hpp"

namespace efg::physics {

/// N and M (per unit length) of a section of thickness t with `points` Gauss points from the
/// membrane strain eps and the curvature kappa; old_states and new_states hold
/// j2_state::count doubles per thickness point (old: at the start of the step; new: written).
/// `p` is used as plane-stress small-strain J2 whatever its flags say.
EFG_PHYSICS_FUNCTION void j2_section_resultants(J2Parameters p, double t, int points,
                                                const double (&eps)[3], const double (&kappa)[3],
                                                const double* old_states, double* new_states,
                                                double dt, double (&N)[3], double (&M)[3]) {
  p.small_strain = true;
  p.plane_stress = true;
  double xi[max_thickness_points], w[max_thickness_points];
  const int n = thickness_rule(points, xi, w);
  for (int i = 0; i < 3; ++i) N[i] = M[i] = 0.0;
  for (int k = 0; k < n; ++k) {
    const double z = 0.5 * t * xi[k], dz = 0.5 * t * w[k];
    const double e[3] = {eps[0] + z * kappa[0], eps[1] + z * kappa[1], eps[2] + z * kappa[2]};
    const double H[2][2] = {{e[0], 0.5 * e[2]}, {0.5 * e[2], e[1]}};
    double old_state[j2_state::count], new_state[j2_state::count], P[2][2], cauchy[3][3];
    for (int s = 0; s < j2_state::count; ++s) old_state[s] = old_states[k * j2_state::count + s];
    j2_update<double, 2>(p, H, old_state, dt, P, new_state, cauchy);
    for (int s = 0; s < j2_state::count; ++s) new_states[k * j2_state::count + s] = new_state[s];
    const double sigma[3] = {P[0][0], P[1][1], P[0][1]};
    for (int i = 0; i < 3; ++i) {
      N[i] += sigma[i] * dz;
      M[i] += sigma[i] * z * dz;
    }
  }
}

/// The stress (xx, yy, xy) of one layer k of such a section at the strains eps, kappa, from its
/// state (the committed one: on the yield surface the return then gives its stress back).
EFG_PHYSICS_FUNCTION void j2_layer_stress(J2Parameters p, double t, int points, int k,
                                          const double (&eps)[3], const double (&kappa)[3],
                                          const double* states, double (&sigma)[3]) {
  p.small_strain = true;
  p.plane_stress = true;
  double xi[max_thickness_points], w[max_thickness_points];
  thickness_rule(points, xi, w);
  const double z = 0.5 * t * xi[k];
  const double e[3] = {eps[0] + z * kappa[0], eps[1] + z * kappa[1], eps[2] + z * kappa[2]};
  const double H[2][2] = {{e[0], 0.5 * e[2]}, {0.5 * e[2], e[1]}};
  double old_state[j2_state::count], new_state[j2_state::count], P[2][2], cauchy[3][3];
  for (int s = 0; s < j2_state::count; ++s) old_state[s] = states[k * j2_state::count + s];
  j2_update<double, 2>(p, H, old_state, 0.0, P, new_state, cauchy);
  sigma[0] = P[0][0];
  sigma[1] = P[1][1];
  sigma[2] = P[0][1];
}

}  // namespace efg::physics
