// Rotary inertia of explicit shells. The true rotary inertia of a Reissner-Mindlin section is
// rho t^3 / 12 per area, i.e. the translational mass times t^2 / 12. With it the rotations of a
// thin shell vibrate against the transverse shear stiffness at omega^2 = 12 k_s G / (rho t^2),
// so the stable step of central differences would fall with the thickness, not with the particle
// spacing h. Explicit shell codes therefore scale the rotary inertia (Key & Beisinger 1971;
// Hughes & Liu 1981; LS-DYNA's shells): here to the inertia of a section as thick as the
// spacing, mass x max(t^2, h^2) / 12, which puts that frequency at 12 k_s G / (rho h^2), about
// the membrane's highest, (2 c / h)^2 with c^2 = E / (rho (1 - nu^2)).
// The price is in the bending modes: a wave of number k is slowed by about (h k)^2 / 24 relative
// (Rayleigh's rotary-inertia correction, omega^2 = D k^4 / (rho t (1 + (I / rho t) k^2))), 0.3 %
// for the first mode of a square plate on 16 x 16 cells, and the error falls with h^2
// (docs/shells.md, "Explicit stages").
#pragma once

#include <algorithm>

namespace efg {

/// The rotary inertia of a particle as a multiple of its translational mass.
inline double shell_rotary_inertia_factor(double thickness, double spacing) {
  const double s = std::max(thickness, spacing);
  return s * s / 12.0;
}

}  // namespace efg
