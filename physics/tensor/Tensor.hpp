// Small dense tensor helpers for Dim x Dim arrays (Dim = 2 or 3).
#pragma once

#include "tensor/Inline.hpp"

namespace efg::physics {

template <int Dim>
EFG_PHYSICS_FUNCTION double determinant(const double (&a)[Dim][Dim]) {
  if constexpr (Dim == 2) {
    return a[0][0] * a[1][1] - a[0][1] * a[1][0];
  } else {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  }
}

/// det(I + h) - 1 without forming 1 + h: tr h + (sum of the principal 2 x 2 minors) + det h
/// (Cayley-Hamilton), so that a nearly isochoric J keeps the digits of J - 1 (ln J = log1p).
template <int Dim>
EFG_PHYSICS_FUNCTION double determinant_of_identity_plus_minus_one(const double (&h)[Dim][Dim]) {
  if constexpr (Dim == 2) {
    return h[0][0] + h[1][1] + (h[0][0] * h[1][1] - h[0][1] * h[1][0]);
  } else {
    const double minors = h[0][0] * h[1][1] - h[0][1] * h[1][0] + h[0][0] * h[2][2] -
                          h[0][2] * h[2][0] + h[1][1] * h[2][2] - h[1][2] * h[2][1];
    return h[0][0] + h[1][1] + h[2][2] + minors + determinant<3>(h);
  }
}

/// inv = a^-1 given det = det(a) != 0.
template <int Dim>
EFG_PHYSICS_FUNCTION void inverse(const double (&a)[Dim][Dim], double det,
                                  double (&inv)[Dim][Dim]) {
  if constexpr (Dim == 2) {
    inv[0][0] = a[1][1] / det, inv[0][1] = -a[0][1] / det;
    inv[1][0] = -a[1][0] / det, inv[1][1] = a[0][0] / det;
  } else {
    inv[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / det;
    inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / det;
    inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / det;
    inv[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / det;
    inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / det;
    inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / det;
    inv[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / det;
    inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / det;
    inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / det;
  }
}

/// A symmetric 3 x 3 tensor from its 6 stored components (xx, yy, zz, xy, yz, xz), and back
/// (the mean of a and a^T): the history columns of the plastic laws.
EFG_PHYSICS_FUNCTION void unpack_symmetric(const double* s, double (&a)[3][3]) {
  for (int k = 0; k < 6; ++k) {
    const int i = k < 3 ? k : k - 3, j = k < 3 ? k : (k - 2) % 3;
    a[i][j] = a[j][i] = s[k];
  }
}

EFG_PHYSICS_FUNCTION void pack_symmetric(const double (&a)[3][3], double* s) {
  for (int k = 0; k < 6; ++k) {
    const int i = k < 3 ? k : k - 3, j = k < 3 ? k : (k - 2) % 3;
    s[k] = 0.5 * (a[i][j] + a[j][i]);
  }
}

/// F = I + H as a 3 x 3 array from a Dim x Dim displacement gradient (F33 = 1 in 2D).
template <class T, int Dim>
EFG_PHYSICS_FUNCTION void deformation_gradient_3x3(const T (&H)[Dim][Dim], T (&F)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      F[i][j] = i < Dim && j < Dim ? H[i][j] : T(0.0);
      if (i == j) F[i][j] += 1.0;
    }
}

/// b_e = F Cp^-1 F^T, the elastic left Cauchy-Green tensor of the multiplicative split (the
/// plastic laws' trial state; symmetric by construction).
template <class T>
EFG_PHYSICS_FUNCTION void elastic_left_cauchy_green(const T (&F)[3][3],
                                                    const double (&cp_inverse)[3][3],
                                                    T (&be)[3][3]) {
  T fc[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      fc[i][j] = F[i][0] * cp_inverse[0][j];
      for (int k = 1; k < 3; ++k) fc[i][j] += F[i][k] * cp_inverse[k][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      be[i][j] = fc[i][0] * F[j][0];
      for (int k = 1; k < 3; ++k) be[i][j] += fc[i][k] * F[j][k];
      be[j][i] = be[i][j];
    }
}

}  // namespace efg::physics
