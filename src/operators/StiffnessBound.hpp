// A guaranteed upper bound on the largest eigenvalue of M^-1 K that needs no iteration (the stable
// time step of drivers/StableTimeStep), from the same integration points as the internal force.
//
// K = sum_q w_q B_q^T A_q B_q (SolidKernels.hpp), so for any x, with H_q(x)_ij = sum_I x_Ii B_qI,j,
//   x^T K x = sum_q w_q H_q : A_q : H_q <= sum_q w_q a_q |H_q|^2,
// a_q >= 0 a bound on the largest eigenvalue of sym(A_q) (Gershgorin on its Dim^2 rows). Cauchy-
// Schwarz on every H_ij = sum_I x_Ii B_Ij, with S_j = sum_I |B_Ij|:
//   H_ij^2 <= S_j sum_I |B_Ij| x_Ii^2   =>   x^T K x <= sum_I,i c_I x_Ii^2,
//   c_I = sum_q w_q a_q sum_j |B_qI,j| S_qj,
// so that lambda_max(M^-1 K) <= max_(I,i) c_I / m_Ii (Rayleigh quotient of M^-1/2 K M^-1/2). For
// linear 1D elements this is the exact 4 E / (rho h^2); in general it is 1.5-4 times lambda_max
// (the Cauchy-Schwarz step, and 3K >= lambda + 2 mu in a_q), which is why it is the floor under a
// sharper Lanczos estimate, not the estimate itself (docs/explicit.md, "Stable time step").
#pragma once

#include <cmath>

#include "operators/SolidKernels.hpp"

namespace efg {

/// a_q: the largest Gershgorin row sum of sym(A), A as a Dim^2 x Dim^2 matrix (A[i][j][k][l]
/// row ij, column kl); 0 when negative (the bound needs a_q >= 0).
template <int Dim>
KOKKOS_INLINE_FUNCTION double tangent_row_bound(const double (&A)[Dim][Dim][Dim][Dim]) {
  constexpr int n = Dim * Dim;
  const double* a = &A[0][0][0][0];
  double largest = 0.0;
  for (int r = 0; r < n; ++r) {
    double row = 0.0;
    for (int c = 0; c < n; ++c) row += fabs(0.5 * (a[r * n + c] + a[c * n + r]));
    largest = row > largest ? row : largest;
  }
  return largest;
}

/// Pass 1: per point q, the terms w_q a_q sum_j |B_k,j| S_j of its entries, into their slots
/// (column 0 of `term`, in by_node order). `inverted` as in PointTangentKernel.
template <int Dim, class DisplacementView>
struct PointStiffnessBoundKernel {
  DevicePoints p;
  DisplacementView u;
  DeviceView<double**> term;
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], P[Dim][Dim], A[Dim][Dim][Dim][Dim];
    displacement_gradient<Dim>(p, u, q, H);
    double a = 0.0;
    if (point_stress<Dim>(p.material, q, H, P, A))
      a = tangent_row_bound<Dim>(A);
    else
      Kokkos::atomic_fetch_min(&inverted(), q);
    double S[Dim];
    for (int j = 0; j < Dim; ++j) S[j] = 0.0;
    for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k)
      for (int j = 0; j < Dim; ++j) S[j] += fabs(p.grad(k, j));
    const double wa = p.weight(q) * a;
    for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k) {
      double s = 0.0;
      for (int j = 0; j < Dim; ++j) s += fabs(p.grad(k, j)) * S[j];
      term(p.slot(k), 0) = wa * s;
    }
  }
};

/// Pass 2: c(I, i) += the terms of I's slots (the same for every component i).
template <int Dim, class RowView>
struct NodalStiffnessBoundKernel {
  DevicePoints p;
  DeviceView<const double**> term;
  RowView c;

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const {
    double sum = 0.0;
    for (auto e = p.by_node.offsets(n); e < p.by_node.offsets(n + 1); ++e) sum += term(e, 0);
    for (int i = 0; i < Dim; ++i) c(n * Dim + i) += sum;
  }
};

}  // namespace efg
