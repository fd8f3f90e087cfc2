// Complete polynomial bases of the MLS approximation, evaluated in shifted and scaled
// coordinates xi = (X_I - x) / s so that the moment matrix is well conditioned whatever the
// model's units (Liu, Li, Belytschko 1997; Chen et al. 2017 review, sec. 3).
//   linear:    1, xi_1 .. xi_d                                   (1 + d terms)
//   quadratic: linear terms, then xi_i xi_j for i <= j            (1 + d + d(d+1)/2 terms)
#pragma once

#include <Kokkos_Macros.hpp>

namespace efg {

template <int Dim, int Order>
struct PolynomialBasis {
  static_assert(Dim >= 1 && Dim <= 3 && (Order == 1 || Order == 2), "unsupported basis");
  static constexpr int size = Order == 1 ? 1 + Dim : 1 + Dim + Dim * (Dim + 1) / 2;

  /// p(xi) into p[size].
  KOKKOS_INLINE_FUNCTION static void values(const double* xi, double* p) {
    p[0] = 1.0;
    for (int i = 0; i < Dim; ++i) p[1 + i] = xi[i];
    if constexpr (Order == 2) {
      int k = 1 + Dim;
      for (int i = 0; i < Dim; ++i)
        for (int j = i; j < Dim; ++j) p[k++] = xi[i] * xi[j];
    }
  }

  /// dp/dxi_d into dp[d][size].
  KOKKOS_INLINE_FUNCTION static void derivatives(const double* xi, double (*dp)[size]) {
    for (int d = 0; d < Dim; ++d) {
      for (int m = 0; m < size; ++m) dp[d][m] = 0.0;
      dp[d][1 + d] = 1.0;
      if constexpr (Order == 2) {
        int k = 1 + Dim;
        for (int i = 0; i < Dim; ++i)
          for (int j = i; j < Dim; ++j, ++k)
            dp[d][k] = (i == d ? xi[j] : 0.0) + (j == d ? xi[i] : 0.0);
      }
    }
  }
};

}  // namespace efg
