// The isochoric (deviatoric) part of a neo-Hookean solid, for mixed u-p parts whose volumetric
// energy U(J) is carried by the cell pressure (operators/MixedPressure; Simo & Hughes,
// "Computational Inelasticity", 1998, sec. 9.2; Bonet & Wood, 2nd ed., sec. 6.5):
//
//   W = mu/2 (J^(-2/3) I1 - 3),   I1 = tr(F^T F),  J = det F   (plane strain: F_33 = 1),
//   P_iJ = c (F_iJ - I1/3 F^-1_Ji),   c = mu J^(-2/3),
//   A_iJkL = dP_iJ/dF_kL = c [d_ik d_JL - 2/3 F^-1_Ji F_kL - 2/3 F_iJ F^-1_Lk
//                             + 2/9 I1 F^-1_Ji F^-1_Lk + I1/3 F^-1_Jk F^-1_Li],
//   Cauchy sigma = mu J^(-5/3) dev(b), b = F F^T (3 x 3).
// W is unchanged by a volume change (W(s F) = W(F)): J^(-2/3) I1 is scale-free.
#pragma once

#include <math.h>  // cbrt: callable in host and device code

#include "tensor/Inline.hpp"
#include "tensor/Tensor.hpp"

namespace efg::physics {

/// P and, when given, A = dP/dH at H = F - I. Returns false when det F <= 0.
template <int Dim>
EFG_PHYSICS_FUNCTION bool isochoric_neo_hookean_stress(double mu, const double (&H)[Dim][Dim],
                                                       double (&P)[Dim][Dim],
                                                       double (*A)[Dim][Dim][Dim] = nullptr) {
  double F[Dim][Dim], Finv[Dim][Dim];
  double I1 = Dim == 2 ? 1.0 : 0.0;  // plane strain: F_33 = 1
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
      I1 += F[i][j] * F[i][j];
    }
  const double J = determinant<Dim>(F);
  if (!(J > 0)) return false;
  inverse<Dim>(F, J, Finv);
  const double c = mu / cbrt(J * J);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      P[i][a] = c * (F[i][a] - I1 / 3.0 * Finv[a][i]);
      if (A)
        for (int k = 0; k < Dim; ++k)
          for (int b = 0; b < Dim; ++b)
            A[i][a][k][b] =
                c * ((i == k && a == b ? 1.0 : 0.0) - 2.0 / 3.0 * Finv[a][i] * F[k][b] -
                     2.0 / 3.0 * F[i][a] * Finv[b][k] + 2.0 / 9.0 * I1 * Finv[a][i] * Finv[b][k] +
                     I1 / 3.0 * Finv[a][k] * Finv[b][i]);
    }
  return true;
}

/// W per unit reference volume (0 for an inverted point).
template <int Dim>
EFG_PHYSICS_FUNCTION double isochoric_neo_hookean_energy(double mu, const double (&H)[Dim][Dim]) {
  double F[Dim][Dim], I1 = Dim == 2 ? 1.0 : 0.0;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
      I1 += F[i][j] * F[i][j];
    }
  const double J = determinant<Dim>(F);
  if (!(J > 0)) return 0.0;
  return 0.5 * mu * (I1 / cbrt(J * J) - 3.0);
}

/// Cauchy stress mu J^(-5/3) dev(b), 3 x 3 (zero for an inverted point).
template <int Dim>
EFG_PHYSICS_FUNCTION void isochoric_neo_hookean_cauchy(double mu, const double (&H)[Dim][Dim],
                                                       double (&sigma)[3][3]) {
  double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) F[i][j] += H[i][j];
  const double J = determinant<3>(F);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sigma[i][j] = 0.0;
  if (!(J > 0)) return;
  double b[3][3], I1 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      b[i][j] = 0;
      for (int k = 0; k < 3; ++k) b[i][j] += F[i][k] * F[j][k];
    }
  for (int i = 0; i < 3; ++i) I1 += b[i][i];
  const double c = mu / (J * cbrt(J * J));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sigma[i][j] = c * (b[i][j] - (i == j ? I1 / 3.0 : 0.0));
}

}  // namespace efg::physics
