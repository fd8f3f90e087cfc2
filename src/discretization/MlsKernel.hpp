// The Kokkos kernel evaluating moving least squares (equivalently reproducing kernel) shape
// functions and their gradients at a batch of points, one point per work item.
//
//   A(x)       = sum_J w_J(x) p(xi_J) p(xi_J)^T,      xi_J = (X_J - x) / s     (moment matrix)
//   phi_I(x)   = p(0)^T A^-1(x) p(xi_I) w_I(x) = b^T p(xi_I) w_I,  A b = p(0) = e_1
//   dphi_I/dx_k = (db/dx_k)^T p_I w_I + b^T (dp_I/dx_k) w_I + b^T p_I dw_I/dx_k,
//   db/dx_k    = -A^-1 (dA/dx_k) b,   dp_I/dx_k = -(1/s) dp/dxi_k
// (Belytschko, Lu, Gu 1994 eqs. 7-14; Chen et al. 1996 for the shifted basis). The shifted and
// scaled basis leaves phi unchanged (it spans the same polynomials) but keeps A well
// conditioned; s is the mean support size of the point's neighbours.
//
// Compile-time dimension and basis size, fixed-size arrays, no allocation, no virtual calls:
// the same code runs on Serial, OpenMP or CUDA execution spaces. Each work item writes only its
// own point's entries, so no atomics are needed.
#pragma once

#include "core/DeviceArrays.hpp"
#include "discretization/KernelFunctions.hpp"
#include "discretization/PolynomialBasis.hpp"
#include "discretization/SmallMatrix.hpp"

namespace efg {

/// Outcome of one point's evaluation, written to MlsKernel::status.
enum MlsStatus : int {
  mls_ok = 0,
  mls_too_few_neighbors = 1,
  mls_singular = 2,
  mls_not_finite = 3
};

template <int Dim, int Order>
struct MlsKernel {
  using Basis = PolynomialBasis<Dim, Order>;
  static constexpr int N = Basis::size;

  DeviceView<const double**> points;     // points x Dim
  DeviceView<const double**> particles;  // particles x Dim, reference positions
  DeviceView<const double**> support;    // particles x Dim, support half-widths
  DeviceView<const std::size_t*> offsets;
  DeviceView<const int*> neighbors;
  DeviceView<double*> phi;        // per neighbour entry
  DeviceView<double**> grad;      // per neighbour entry x Dim (unused without gradients)
  DeviceView<double*> condition;  // per point: 1-norm condition number of A
  DeviceView<int*> status;        // per point: MlsStatus
  KernelShape kernel = KernelShape::cubic_spline;
  bool sphere = false;
  bool with_gradients = true;
  double pivot_floor = 1e-14;

  KOKKOS_INLINE_FUNCTION void weight(int j, const double* x, double& w, double* dw) const {
    if (sphere) {
      const double a = support(j, 0);
      double r2 = 0;
      for (int d = 0; d < Dim; ++d) r2 += (x[d] - particles(j, d)) * (x[d] - particles(j, d));
      const double r = Kokkos::Experimental::sqrt(r2) / a;
      const auto k = kernel_value(kernel, r);
      w = k.w;
      for (int d = 0; d < Dim; ++d)
        dw[d] = r > 0 ? k.dw_dr * (x[d] - particles(j, d)) / (r * a * a) : 0.0;
      return;
    }
    double value[Dim], slope[Dim];
    for (int d = 0; d < Dim; ++d) {
      const double dx = x[d] - particles(j, d);
      const double r = (dx < 0 ? -dx : dx) / support(j, d);
      const auto k = kernel_value(kernel, r);
      value[d] = k.w;
      slope[d] = k.dw_dr * (dx < 0 ? -1.0 : 1.0) / support(j, d);
    }
    w = 1.0;
    for (int d = 0; d < Dim; ++d) w *= value[d];
    for (int d = 0; d < Dim; ++d) {
      dw[d] = slope[d];
      for (int e = 0; e < Dim; ++e)
        if (e != d) dw[d] *= value[e];
    }
  }

  KOKKOS_INLINE_FUNCTION void basis_at(int j, const double* x, double s, double* p,
                                       double (*dp)[N]) const {
    double xi[Dim];
    for (int d = 0; d < Dim; ++d) xi[d] = (particles(j, d) - x[d]) / s;
    Basis::values(xi, p);
    if (with_gradients) {
      Basis::derivatives(xi, dp);
      for (int d = 0; d < Dim; ++d)
        for (int m = 0; m < N; ++m) dp[d][m] *= -1.0 / s;  // d xi / d x = -1 / s
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int point) const {
    double x[Dim];
    for (int d = 0; d < Dim; ++d) x[d] = points(point, d);
    const std::size_t begin = offsets(point), end = offsets(point + 1);
    if (end - begin < static_cast<std::size_t>(N)) {
      status(point) = mls_too_few_neighbors;
      condition(point) = 0.0;
      return;
    }
    double s = 0.0;
    for (std::size_t k = begin; k < end; ++k)
      for (int d = 0; d < Dim; ++d) s += support(neighbors(k), d);
    s /= static_cast<double>((end - begin) * Dim);

    double A[N][N] = {};
    double dA[Dim][N][N] = {};
    double p[N], dp[Dim][N], dw[Dim];
    for (std::size_t k = begin; k < end; ++k) {
      const int j = neighbors(k);
      double w;
      weight(j, x, w, dw);
      // Kept in the output slots for the second pass (same bits as evaluating them again).
      phi(k) = w;
      if (with_gradients)
        for (int d = 0; d < Dim; ++d) grad(k, d) = dw[d];
      basis_at(j, x, s, p, dp);
      for (int m = 0; m < N; ++m)
        for (int n = 0; n < N; ++n) {
          A[m][n] += w * p[m] * p[n];
          if (with_gradients)
            for (int d = 0; d < Dim; ++d)
              dA[d][m][n] += dw[d] * p[m] * p[n] + w * (dp[d][m] * p[n] + p[m] * dp[d][n]);
        }
    }
    double Ainv[N][N];
    if (!invert_small<N>(A, Ainv, pivot_floor)) {
      status(point) = mls_singular;
      condition(point) = 0.0;
      return;
    }
    status(point) = mls_ok;
    condition(point) = norm1_small<N>(A) * norm1_small<N>(Ainv);
    // b = A^-1 e_1; db_d = -A^-1 dA_d b.
    double b[N], db[Dim][N];
    for (int m = 0; m < N; ++m) b[m] = Ainv[m][0];
    if (with_gradients)
      for (int d = 0; d < Dim; ++d) {
        double t[N];
        for (int m = 0; m < N; ++m) {
          t[m] = 0.0;
          for (int n = 0; n < N; ++n) t[m] += dA[d][m][n] * b[n];
        }
        for (int m = 0; m < N; ++m) {
          db[d][m] = 0.0;
          for (int n = 0; n < N; ++n) db[d][m] -= Ainv[m][n] * t[n];
        }
      }
    for (std::size_t k = begin; k < end; ++k) {
      const int j = neighbors(k);
      const double w = phi(k);
      if (with_gradients)
        for (int d = 0; d < Dim; ++d) dw[d] = grad(k, d);
      basis_at(j, x, s, p, dp);
      double bp = 0.0;
      for (int m = 0; m < N; ++m) bp += b[m] * p[m];
      phi(k) = bp * w;
      if (with_gradients)
        for (int d = 0; d < Dim; ++d) {
          double dbp = 0.0, bdp = 0.0;
          for (int m = 0; m < N; ++m) {
            dbp += db[d][m] * p[m];
            bdp += b[m] * dp[d][m];
          }
          grad(k, d) = dbp * w + bdp * w + bp * dw[d];
        }
    }
    // Checked here, in parallel, rather than by the caller over every entry.
    bool finite = true;
    for (std::size_t k = begin; k < end; ++k) {
      finite = finite && Kokkos::Experimental::isfinite(phi(k));
      if (with_gradients)
        for (int d = 0; d < Dim; ++d) finite = finite && Kokkos::Experimental::isfinite(grad(k, d));
    }
    if (!finite) status(point) = mls_not_finite;
  }
};

}  // namespace efg
