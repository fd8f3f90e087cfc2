// The section law of a Reissner-Mindlin plate or shell (first-order shear deformation; Reissner
// 1945, Mindlin 1951): stress resultants from the mid-surface strains.
//
//   N = A eps          membrane forces per unit length,   eps   = (e_xx, e_yy, 2 e_xy)
//   M = D kappa        bending moments per unit length,   kappa = (k_xx, k_yy, 2 k_xy)
//   Q = k_s G t gamma  transverse shear forces per length, gamma = (g_xz, g_yz)
//
// with the plane-stress moduli C of the material integrated through the thickness:
// A = integral C dz, D = integral z^2 C dz over z in [-t/2, t/2]. For a homogeneous elastic
// section A = E t / (1 - nu^2) [1 nu 0; nu 1 0; 0 0 (1 - nu)/2] and D = A t^2 / 12; k_s = 5/6 is
// Reissner's shear correction factor (parabolic shear stress through the thickness). The section
// is integrated numerically through the thickness (Gauss-Legendre, `points` layers) so that a
// path-dependent plane-stress law can later take the elastic C's place point by point; two
// points integrate the elastic section exactly.
#pragma once

#include "materials/SolidMaterial.hpp"

namespace efg::physics {

struct MindlinSection {
  double membrane[3][3] = {};  ///< A
  double bending[3][3] = {};   ///< D
  double shear = 0;            ///< k_s G t (the same for both transverse shear components)
};

/// Plane-stress moduli of an isotropic elastic material in Voigt order (xx, yy, 2 xy).
EFG_PHYSICS_FUNCTION void plane_stress_moduli(double E, double nu, double (&C)[3][3]) {
  const double s = E / (1 - nu * nu);
  const double c[3][3] = {{s, s * nu, 0}, {s * nu, s, 0}, {0, 0, s * (1 - nu) / 2}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[i][j] = c[i][j];
}

/// Most integration points through a shell's thickness.
inline constexpr int max_thickness_points = 12;

/// Gauss-Legendre points (ascending) and weights on [-1, 1] for 1 to max_thickness_points points
/// (the request clamped to that range; returns the number used): the roots of P_n by Newton's
/// method from Tricomi's estimate cos(pi (i + 3/4) / (n + 1/2)), w = 2 / ((1 - x^2) P_n'(x)^2)
/// (Abramowitz & Stegun 25.4.29).
EFG_PHYSICS_FUNCTION int thickness_rule(int points, double (&xi)[max_thickness_points],
                                        double (&w)[max_thickness_points]) {
  const int n = points < 1 ? 1 : (points > max_thickness_points ? max_thickness_points : points);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double x = cos(pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;  // P_0, P_1, then up to P_n by Bonnet's recursion
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pm = n == 1 ? 1.0 : p0;
      dp = n * (x * pn - pm) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (fabs(dx) < 1e-16) break;
    }
    xi[n - 1 - i] = x;
    w[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return n;
}

/// The section of a homogeneous isotropic elastic layer of thickness t, integrated through the
/// thickness with `points` Gauss points (>= 2 is exact).
EFG_PHYSICS_FUNCTION MindlinSection elastic_mindlin_section(double E, double nu, double t,
                                                            int points = 2,
                                                            double shear_factor = 5.0 / 6.0) {
  MindlinSection s;
  double C[3][3], xi[max_thickness_points], w[max_thickness_points];
  plane_stress_moduli(E, nu, C);
  const int n = thickness_rule(points, xi, w);
  for (int k = 0; k < n; ++k) {
    const double z = 0.5 * t * xi[k], dz = 0.5 * t * w[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        s.membrane[i][j] += C[i][j] * dz;
        s.bending[i][j] += C[i][j] * z * z * dz;
      }
  }
  s.shear = shear_factor * E / (2 * (1 + nu)) * t;
  return s;
}

/// The section with its transverse shear stiffness limited on a grid of spacing h (Lyly, Stenberg
/// & Vihinen, CMAME 110 (1993) 343-357; Pitkaranta 1988): k_s G t -> k_s G t t^2 / (t^2 + alpha
/// h^2). When t >> h it is the shear stiffness itself; when t << h it is of the order of the
/// bending stiffness D / h^2, so the discrete Kirchhoff constraints do not outnumber the free
/// dofs (shear locking) on coarse grids. Constant-bending states (zero shear strain) are
/// unaffected, so the patch tests still hold; the thin-limit error it adds falls like h^2.
EFG_PHYSICS_FUNCTION MindlinSection with_stabilized_shear(MindlinSection s, double t, double h,
                                                          double alpha) {
  s.shear *= t * t / (t * t + alpha * h * h);
  return s;
}

/// Resultants N, M, Q of the strains (see the header comment for the ordering).
EFG_PHYSICS_FUNCTION void mindlin_resultants(const MindlinSection& s, const double (&eps)[3],
                                             const double (&kappa)[3], const double (&gamma)[2],
                                             double (&N)[3], double (&M)[3], double (&Q)[2]) {
  for (int i = 0; i < 3; ++i) {
    N[i] = M[i] = 0;
    for (int j = 0; j < 3; ++j) {
      N[i] += s.membrane[i][j] * eps[j];
      M[i] += s.bending[i][j] * kappa[j];
    }
  }
  for (int i = 0; i < 2; ++i) Q[i] = s.shear * gamma[i];
}

}  // namespace efg::physics
