// Kernel (weight) functions w(r) of the normalized distance r = |x - X_I| / a_I, compactly
// supported on r < 1, and their derivatives dw/dr. Plain inline functions callable from Kokkos
// kernels.
//
//   cubic spline   (Belytschko, Lu, Gu 1994; Kambur 2004 eq. 3.17):
//     2/3 - 4 r^2 + 4 r^3                 r <= 1/2
//     4/3 - 4 r + 4 r^2 - 4/3 r^3         1/2 < r <= 1
//   quartic spline (Belytschko et al. 1994; Kambur 2004 eq. 3.18):
//     1 - 6 r^2 + 8 r^3 - 3 r^4           r <= 1
//   quadratic spline: the C1 quadratic B-spline of the reproducing kernel particle method
//     (Liu, Jun, Zhang 1995), scaled to support 1 and w(0) = 1:
//     1 - 3 r^2                           r <= 1/3
//     3/2 (1 - r)^2                       1/3 < r <= 1
//   (Kambur's scanned equation for the quadratic spline is illegible; this is the kernel of the
//   RKPM literature LS-DYNA's EFG descends from.)
#pragma once

#include <Kokkos_Macros.hpp>

namespace efg {

enum class KernelShape : int { cubic_spline = 0, quadratic_spline = 1, quartic_spline = 2 };

struct KernelValue {
  double w;
  double dw_dr;
};

KOKKOS_INLINE_FUNCTION KernelValue kernel_value(KernelShape shape, double r) {
  if (r >= 1.0) return {0.0, 0.0};
  switch (shape) {
    case KernelShape::cubic_spline:
      if (r <= 0.5) return {2.0 / 3.0 - 4.0 * r * r + 4.0 * r * r * r, -8.0 * r + 12.0 * r * r};
      return {4.0 / 3.0 - 4.0 * r + 4.0 * r * r - 4.0 / 3.0 * r * r * r,
              -4.0 + 8.0 * r - 4.0 * r * r};
    case KernelShape::quartic_spline:
      return {1.0 - 6.0 * r * r + 8.0 * r * r * r - 3.0 * r * r * r * r,
              -12.0 * r + 24.0 * r * r - 12.0 * r * r * r};
    case KernelShape::quadratic_spline:
      if (r <= 1.0 / 3.0) return {1.0 - 3.0 * r * r, -6.0 * r};
      return {1.5 * (1.0 - r) * (1.0 - r), -3.0 * (1.0 - r)};
  }
  return {0.0, 0.0};
}

}  // namespace efg
