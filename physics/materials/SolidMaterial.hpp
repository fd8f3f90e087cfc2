// Stress, tangent and strain energy of the solid materials, as functions of the displacement
// gradient H = du/dX at one point (Dim = 2: plane strain, or plane stress for small strain).
//
//   small strain, linear elastic: eps = sym(H), sigma = lambda tr(eps) I + 2 mu eps,
//     P = sigma, A = dP/dH = C (the isotropic elasticity tensor), W = 1/2 eps : C : eps.
//   finite strain, compressible neo-Hookean (Bonet & Wood, "Nonlinear Continuum Mechanics for
//     Finite Element Analysis", 2nd ed., eqs. 6.27-6.29 and 6.40):
//     F = I + H, J = det F,  W = mu/2 (tr(F^T F) - 3) - mu ln J + lambda/2 (ln J)^2,
//     P = mu (F - F^-T) + lambda ln J F^-T,
//     A_iJkL = dP_iJ/dF_kL = mu d_ik d_JL + (mu - lambda ln J) F^-1_Li F^-1_Jk + lambda F^-1_Ji F^-1_Lk,
//     Cauchy sigma = 1/J (mu (b - I) + lambda ln J I), b = F F^T.
//   In 2D plane strain F_33 = 1 (the 3D formulas restricted to the plane; tr(F^T F) gains 1).
#pragma once

#include <math.h>  // log, sqrt: callable in host and device code

#include "materials/IsochoricNeoHookean.hpp"
#include "tensor/Inline.hpp"
#include "tensor/Tensor.hpp"

namespace efg::physics {

/// isochoric_neo_hookean: the deviatoric part of neo_hookean for mixed u-p parts
/// (materials/IsochoricNeoHookean.hpp; lambda unused, the cell pressure carries the volume).
enum class MaterialKind : int { linear_elastic = 0, neo_hookean = 1, isochoric_neo_hookean = 2 };

struct SolidMaterial {
  MaterialKind kind = MaterialKind::linear_elastic;
  double lambda = 0.0;  ///< Lame's first parameter (plane stress: the reduced lambda*)
  double mu = 0.0;      ///< shear modulus
  bool plane_stress = false;
};

/// The law with both Lame constants scaled by s: a graded material at a point, s = E(x) / E_ref
/// (nu fixed, so lambda and mu scale with E).
EFG_PHYSICS_FUNCTION SolidMaterial with_moduli_scaled(SolidMaterial m, double s) {
  m.lambda *= s;
  m.mu *= s;
  return m;
}

/// P (first Piola-Kirchhoff; the Cauchy stress for small strain), and A = dP/dH when `A` is
/// given. Returns false when det F <= 0 (finite strain): the point is inverted and P, A are
/// undefined.
template <int Dim>
EFG_PHYSICS_FUNCTION bool stress(const SolidMaterial& m, const double (&H)[Dim][Dim],
                                 double (&P)[Dim][Dim], double (*A)[Dim][Dim][Dim] = nullptr) {
  if (m.kind == MaterialKind::isochoric_neo_hookean)
    return isochoric_neo_hookean_stress<Dim>(m.mu, H, P, A);
  if (m.kind == MaterialKind::linear_elastic) {
    double tr = 0;
    for (int i = 0; i < Dim; ++i) tr += H[i][i];
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) {
        P[i][j] = m.mu * (H[i][j] + H[j][i]) + (i == j ? m.lambda * tr : 0.0);
        if (A)
          for (int k = 0; k < Dim; ++k)
            for (int l = 0; l < Dim; ++l)
              A[i][j][k][l] =
                  (i == j && k == l ? m.lambda : 0.0) +
                  m.mu * ((i == k && j == l ? 1.0 : 0.0) + (i == l && j == k ? 1.0 : 0.0));
      }
    return true;
  }
  double F[Dim][Dim], Finv[Dim][Dim];
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
  const double J = determinant<Dim>(F);
  if (!(J > 0)) return false;
  inverse<Dim>(F, J, Finv);
  const double lnJ = log(J);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      P[i][a] = m.mu * (F[i][a] - Finv[a][i]) + m.lambda * lnJ * Finv[a][i];
      if (A)
        for (int k = 0; k < Dim; ++k)
          for (int b = 0; b < Dim; ++b)
            A[i][a][k][b] = (i == k && a == b ? m.mu : 0.0) +
                            (m.mu - m.lambda * lnJ) * Finv[b][i] * Finv[a][k] +
                            m.lambda * Finv[a][i] * Finv[b][k];
    }
  return true;
}

/// P and A = dP/dH (see stress).
template <int Dim>
EFG_PHYSICS_FUNCTION bool stress_and_tangent(const SolidMaterial& m, const double (&H)[Dim][Dim],
                                             double (&P)[Dim][Dim],
                                             double (&A)[Dim][Dim][Dim][Dim]) {
  return stress<Dim>(m, H, P, A);
}

/// Strain energy per unit reference volume (0 for an inverted point).
template <int Dim>
EFG_PHYSICS_FUNCTION double strain_energy(const SolidMaterial& m, const double (&H)[Dim][Dim]) {
  if (m.kind == MaterialKind::isochoric_neo_hookean)
    return isochoric_neo_hookean_energy<Dim>(m.mu, H);
  if (m.kind == MaterialKind::linear_elastic) {
    double tr = 0, ee = 0;
    for (int i = 0; i < Dim; ++i) tr += H[i][i];
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) {
        const double e = 0.5 * (H[i][j] + H[j][i]);
        ee += e * e;
      }
    return 0.5 * m.lambda * tr * tr + m.mu * ee;
  }
  double F[Dim][Dim], trC = Dim == 2 ? 1.0 : 0.0;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
      trC += F[i][j] * F[i][j];
    }
  const double J = determinant<Dim>(F);
  if (!(J > 0)) return 0.0;
  const double lnJ = log(J);
  return 0.5 * m.mu * (trC - 3.0) - m.mu * lnJ + 0.5 * m.lambda * lnJ * lnJ;
}

/// Cauchy stress as a full 3 x 3 tensor (2D: sigma_zz from plane strain; 0 in plane stress).
template <int Dim>
EFG_PHYSICS_FUNCTION void cauchy_stress(const SolidMaterial& m, const double (&H)[Dim][Dim],
                                        double (&sigma)[3][3]) {
  if (m.kind == MaterialKind::isochoric_neo_hookean) {
    isochoric_neo_hookean_cauchy<Dim>(m.mu, H, sigma);
    return;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sigma[i][j] = 0.0;
  if (m.kind == MaterialKind::linear_elastic) {
    double tr = 0;
    for (int i = 0; i < Dim; ++i) tr += H[i][i];
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j)
        sigma[i][j] = m.mu * (H[i][j] + H[j][i]) + (i == j ? m.lambda * tr : 0.0);
    if (Dim == 2 && !m.plane_stress) sigma[2][2] = m.lambda * tr;
    return;
  }
  double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) F[i][j] += H[i][j];
  const double J = determinant<3>(F);
  if (!(J > 0)) return;
  const double lnJ = log(J);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double b = 0;
      for (int k = 0; k < 3; ++k) b += F[i][k] * F[j][k];
      sigma[i][j] = (m.mu * (b - (i == j ? 1.0 : 0.0)) + (i == j ? m.lambda * lnJ : 0.0)) / J;
    }
}

/// von Mises equivalent of a 3 x 3 Cauchy stress.
EFG_PHYSICS_FUNCTION double von_mises(const double (&s)[3][3]) {
  const double a = s[0][0] - s[1][1], b = s[1][1] - s[2][2], c = s[2][2] - s[0][0];
  return sqrt(0.5 * (a * a + b * b + c * c) +
              3.0 * (s[0][1] * s[0][1] + s[1][2] * s[1][2] + s[2][0] * s[2][0]));
}

}  // namespace efg::physics
