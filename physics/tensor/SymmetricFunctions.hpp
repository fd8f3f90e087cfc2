// log and exp of symmetric 3 x 3 matrices (log: positive definite) for the finite-strain material
// laws, templated on the scalar type T (double, or a forward-AD type such as Sacado's SFad that
// has val()), plus the small 3 x 3 helpers they need.
//
// Why no eigen-decomposition: the laws are differentiated by forward AD, and eigenvectors are not
// differentiable where eigenvalues repeat (b_e = I at the start, two equal eigenvalues in every
// uniaxial state), so AD through a Jacobi or Cardano decomposition returns NaN or wrong
// derivatives exactly there. Both functions below use only +, -, x and 3 x 3 inverses: rational
// in the entries for a given count of square roots / squarings (the counts depend on the values
// only), so AD gives the derivative of the computed function at any eigenvalue multiplicity.
//
//   log A: inverse scaling and squaring (Kenney & Laub, SIAM J. Matrix Anal. Appl. 10 (1989)
//     191-209; Higham, "Functions of Matrices", SIAM 2008, sec. 11.5). A = c R0 with
//     c = det(A)^(1/3); R_{k+1} = R_k^(1/2) (product-form Denman-Beavers iteration, Higham 2008
//     eq. (6.29)) until ||R_k - I||_F <= 1/4; then log R_k = 2 atanh(Z), Z = (R_k - I)(R_k + I)^-1,
//     by its Gregory series (|z| <= 1/7: the terms up to z^19 leave a relative truncation error
//     below 1e-18); log A = ln(c) I + 2^k log R_k.
//   exp X: scaling and squaring (Moler & Van Loan, SIAM Review 45 (2003) 3-49, method 3):
//     exp X = e^(tr X / 3) (exp(D / 2^s))^(2^s), D = dev X, ||D||_F / 2^s <= 1/4, with the
//     degree-12 Taylor polynomial (truncation <= 0.25^13 / 13! = 2.4e-18).
// Accuracy (tests/unit/J2PlasticityTest.cpp): exp to a few ulps of the norm of the result; log
// to ~1e-14 relative for lambda_max / lambda_min <= 20 (stretch ratios up to 4.5), beyond that
// ~eps lambda_max / lambda_min, the sensitivity of log A to the rounding of A itself.
#pragma once

#include <math.h>  // log, exp, sqrt, ldexp: callable in host and device code

#include "tensor/Inline.hpp"

namespace efg::physics {

/// The double value of a scalar: itself, or the value part of an AD type.
EFG_PHYSICS_FUNCTION double value_of(double x) {
  return x;
}
template <class T>
EFG_PHYSICS_FUNCTION double value_of(const T& x) {
  return x.val();
}

namespace matrix3 {

template <class T>
EFG_PHYSICS_FUNCTION void multiply(const T (&a)[3][3], const T (&b)[3][3], T (&c)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T s = a[i][0] * b[0][j];
      for (int k = 1; k < 3; ++k) s += a[i][k] * b[k][j];
      c[i][j] = s;
    }
}

template <class T>
EFG_PHYSICS_FUNCTION T determinant(const T (&a)[3][3]) {
  T d = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]);
  d -= a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]);
  d += a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  return d;
}

/// inv = a^-1 by cofactors (a must be invertible).
template <class T>
EFG_PHYSICS_FUNCTION void inverse(const T (&a)[3][3], T (&inv)[3][3]) {
  const T det = determinant(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
      inv[i][j] = (a[j1][i1] * a[j2][i2] - a[j1][i2] * a[j2][i1]) / det;
    }
}

/// Frobenius norm of the value of a - s I.
template <class T>
EFG_PHYSICS_FUNCTION double distance_to_identity(const T (&a)[3][3], double s = 1.0) {
  double n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = value_of(a[i][j]) - (i == j ? s : 0.0);
      n += d * d;
    }
  return sqrt(n);
}

template <class T>
EFG_PHYSICS_FUNCTION void symmetrize(T (&a)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const T m = 0.5 * (a[i][j] + a[j][i]);
      a[i][j] = m;
      a[j][i] = m;
    }
}

/// a <- a^(1/2) for a symmetric positive definite a: product-form Denman-Beavers,
/// M_0 = Y_0 = a, M_{j+1} = (I + (M_j + M_j^-1) / 2) / 2, Y_{j+1} = Y_j (I + M_j^-1) / 2; M -> I
/// quadratically and Y -> a^(1/2). One more step after ||M - I||_F <= 1e-10 puts the value and
/// its derivative at round-off (the error squares each step).
template <class T>
EFG_PHYSICS_FUNCTION void square_root(T (&a)[3][3]) {
  T m[3][3], y[3][3], minv[3][3], w[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = y[i][j] = a[i][j];
  bool last = false;
  for (int iteration = 0; iteration < 60; ++iteration) {
    inverse(m, minv);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        w[i][j] = 0.5 * minv[i][j] + (i == j ? 0.5 : 0.0);
        m[i][j] = 0.25 * (m[i][j] + minv[i][j]) + (i == j ? 0.5 : 0.0);
      }
    multiply(y, w, a);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[i][j] = a[i][j];
    if (last) break;
    last = distance_to_identity(m) <= 1e-10;
  }
  symmetrize(a);
}

}  // namespace matrix3

/// L = log A for a symmetric positive definite A (inverse scaling and squaring; see the top).
template <class T>
EFG_PHYSICS_FUNCTION void symmetric_log(const T (&A)[3][3], T (&L)[3][3]) {
  using namespace matrix3;
  const T log_c = log(determinant(A)) / 3.0;
  const T c = exp(log_c);
  T r[3][3], z[3][3], z2[3][3], s[3][3], t[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = A[i][j] / c;
  int roots = 0;
  while (distance_to_identity(r) > 0.25 && roots < 60) {
    square_root(r);
    ++roots;
  }
  // Z = (R - I)(R + I)^-1; log R = 2 Z (I + Z^2/3 + Z^4/5 + ... + Z^18/19), by Horner in Z^2.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      s[i][j] = r[i][j] + (i == j ? 1.0 : 0.0);
      r[i][j] -= (i == j ? 1.0 : 0.0);
    }
  inverse(s, t);
  multiply(r, t, z);
  symmetrize(z);
  multiply(z, z, z2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = i == j ? 1.0 / 19.0 : 0.0;
  for (int n = 17; n >= 1; n -= 2) {
    multiply(z2, s, t);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[i][j] = t[i][j] + (i == j ? 1.0 / n : 0.0);
  }
  multiply(z, s, t);
  const double scale = ldexp(2.0, roots);  // 2 x 2^roots, exact
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) L[i][j] = scale * t[i][j] + (i == j ? log_c : T(0.0));
  symmetrize(L);
}

/// E = exp X for a symmetric X (scaling and squaring; see the top).
template <class T>
EFG_PHYSICS_FUNCTION void symmetric_exp(const T (&X)[3][3], T (&E)[3][3]) {
  using namespace matrix3;
  const T mean = (X[0][0] + X[1][1] + X[2][2]) / 3.0;
  T d[3][3], t[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      d[i][j] = X[i][j];
      if (i == j) d[i][j] -= mean;
    }
  int squarings = 0;
  for (double n = distance_to_identity(d, 0.0); n > 0.25 && squarings < 60; n *= 0.5) ++squarings;
  const double shrink = ldexp(1.0, -squarings);  // exact
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] *= shrink;
  // exp D = I + D (I + D/2 (I + D/3 (... (I + D/12)))) by Horner.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) E[i][j] = i == j ? 1.0 : 0.0;
  for (int n = 12; n >= 1; --n) {
    multiply(d, E, t);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) E[i][j] = t[i][j] / static_cast<double>(n) + (i == j ? 1.0 : 0.0);
  }
  for (int k = 0; k < squarings; ++k) {
    multiply(E, E, t);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) E[i][j] = t[i][j];
  }
  const T volume = exp(mean);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) E[i][j] *= volume;
  symmetrize(E);
}

}  // namespace efg::physics
