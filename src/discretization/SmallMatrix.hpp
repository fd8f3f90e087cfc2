// Dense LU with partial pivoting for the small moment matrices of MLS (at most 10 x 10), on
// fixed-size arrays, usable inside Kokkos kernels (no allocation, no exceptions).
#pragma once

#include <Kokkos_Macros.hpp>

namespace efg {

/// Inverts a[N][N] into inv[N][N]. Returns false when a pivot is zero or below
/// `relative_pivot_floor` times the largest entry (numerically singular); then inv is undefined.
template <int N>
KOKKOS_INLINE_FUNCTION bool invert_small(const double (&a)[N][N], double (&inv)[N][N],
                                         double relative_pivot_floor) {
  double lu[N][N];
  int perm[N];
  double scale = 0.0;
  for (int i = 0; i < N; ++i) {
    perm[i] = i;
    for (int j = 0; j < N; ++j) {
      lu[i][j] = a[i][j];
      const double v = a[i][j] < 0 ? -a[i][j] : a[i][j];
      scale = v > scale ? v : scale;
    }
  }
  if (!(scale > 0.0)) return false;
  for (int k = 0; k < N; ++k) {
    int p = k;
    double best = lu[k][k] < 0 ? -lu[k][k] : lu[k][k];
    for (int i = k + 1; i < N; ++i) {
      const double v = lu[i][k] < 0 ? -lu[i][k] : lu[i][k];
      if (v > best) {
        best = v;
        p = i;
      }
    }
    if (!(best > relative_pivot_floor * scale)) return false;
    if (p != k) {
      for (int j = 0; j < N; ++j) {
        const double t = lu[k][j];
        lu[k][j] = lu[p][j];
        lu[p][j] = t;
      }
      const int t = perm[k];
      perm[k] = perm[p];
      perm[p] = t;
    }
    for (int i = k + 1; i < N; ++i) {
      lu[i][k] /= lu[k][k];
      for (int j = k + 1; j < N; ++j) lu[i][j] -= lu[i][k] * lu[k][j];
    }
  }
  // Solve for each column of the identity (permuted).
  for (int c = 0; c < N; ++c) {
    double y[N];
    for (int i = 0; i < N; ++i) {
      double s = perm[i] == c ? 1.0 : 0.0;
      for (int j = 0; j < i; ++j) s -= lu[i][j] * y[j];
      y[i] = s;
    }
    for (int i = N - 1; i >= 0; --i) {
      double s = y[i];
      for (int j = i + 1; j < N; ++j) s -= lu[i][j] * inv[j][c];
      inv[i][c] = s / lu[i][i];
    }
  }
  return true;
}

/// The 1-norm of a[N][N] (largest column sum of magnitudes).
template <int N>
KOKKOS_INLINE_FUNCTION double norm1_small(const double (&a)[N][N]) {
  double best = 0.0;
  for (int j = 0; j < N; ++j) {
    double s = 0.0;
    for (int i = 0; i < N; ++i) s += a[i][j] < 0 ? -a[i][j] : a[i][j];
    best = s > best ? s : best;
  }
  return best;
}

}  // namespace efg
