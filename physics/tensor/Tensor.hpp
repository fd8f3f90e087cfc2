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

}  // namespace efg::physics
