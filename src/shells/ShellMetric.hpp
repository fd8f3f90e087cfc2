// The metric of a curved reference over the flat mesh (docs/shells.md "Curved references"): a
// point's generalized strains measured in the mesh coordinates (x1, x2) = (x, y) are covariant
// components; the section law wants them in an orthonormal frame (e1, e2) of the surface.
//
// With the map's tangents A_a = dX/dx_a and J_(a alpha) = A_a . e_alpha, a surface arc is
// ds = J^T dx, so dx_a = M_(a alpha) ds_alpha with M = J^-T, and (Green & Zerna; Simo & Fox
// 1989, eq. 3.11, the strains as tensors of the convected coordinates)
//
//   E_(alpha beta) = M_(a alpha) M_(b beta) E_(ab),   kappa likewise,   gamma_alpha = M_(a alpha) gamma_a
//
// a linear map e = T e_xy of the eight strains (eps, kappa with engineering shears, gamma). The
// resultants conjugate to the covariant strains are T^T R: the virtual work R . T de_xy per unit
// surface area, times the area ratio |A1 x A2| per unit mesh area. An isometry (the unrolled
// developable surface) has J orthogonal with e_a = A_a: M = I, area 1. Plain arrays, no Trilinos.
#pragma once

#include <cmath>

#include "shells/FiniteRotation.hpp"

namespace efg {

struct ShellMetric {
  double M[2][2] = {{1, 0}, {0, 1}};  ///< dx_a = M[a][alpha] ds_alpha
  double area = 1;                    ///< surface area per unit mesh area, |A1 x A2|
};

/// The metric at a point of map tangents A (dX/dx, dX/dy) and orthonormal frame e1, e2 (t1, t2
/// of `frame`, spanning the tangent plane).
inline ShellMetric shell_metric(const Vec3 (&A)[2], const ShellFrame& frame) {
  const double J00 = dot(A[0], frame.t1), J01 = dot(A[0], frame.t2), J10 = dot(A[1], frame.t1),
               J11 = dot(A[1], frame.t2);
  const double det = J00 * J11 - J01 * J10;
  ShellMetric m;
  // M = J^-T: (J^-1)_(alpha a) transposed
  m.M[0][0] = J11 / det;
  m.M[0][1] = -J10 / det;
  m.M[1][0] = -J01 / det;
  m.M[1][1] = J00 / det;
  m.area = std::abs(det);
  return m;
}

namespace shell_metric_detail {
/// T of one symmetric pair (xx, yy, 2 xy) of a strain block.
inline void pair_rows(const ShellMetric& m, double (&T)[3][3]) {
  const auto& M = m.M;
  T[0][0] = M[0][0] * M[0][0];
  T[0][1] = M[1][0] * M[1][0];
  T[0][2] = M[0][0] * M[1][0];
  T[1][0] = M[0][1] * M[0][1];
  T[1][1] = M[1][1] * M[1][1];
  T[1][2] = M[0][1] * M[1][1];
  T[2][0] = 2 * M[0][0] * M[0][1];
  T[2][1] = 2 * M[1][0] * M[1][1];
  T[2][2] = M[0][0] * M[1][1] + M[1][0] * M[0][1];
}
}  // namespace shell_metric_detail

/// The 8 x 8 T (block diagonal: membrane, bending, shear) of e = T e_xy.
inline void strain_transform(const ShellMetric& m, double (&T)[shell_strains][shell_strains]) {
  for (auto& row : T)
    for (auto& v : row) v = 0;
  double P[3][3];
  shell_metric_detail::pair_rows(m, P);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[i][j] = T[3 + i][3 + j] = P[i][j];
  for (int alpha = 0; alpha < 2; ++alpha)
    for (int a = 0; a < 2; ++a) T[6 + alpha][6 + a] = m.M[a][alpha];
}

/// e <- T e (mesh-coordinate strains to the surface frame's).
inline void strains_to_surface(const ShellMetric& m, double (&e)[shell_strains]) {
  double T[shell_strains][shell_strains], out[shell_strains] = {};
  strain_transform(m, T);
  for (int i = 0; i < shell_strains; ++i)
    for (int j = 0; j < shell_strains; ++j) out[i] += T[i][j] * e[j];
  for (int i = 0; i < shell_strains; ++i) e[i] = out[i];
}

/// B <- T B (one particle's strain rows).
inline void rows_to_surface(const ShellMetric& m, double (&B)[shell_strains][shell_dofs_per_node]) {
  double T[shell_strains][shell_strains], out[shell_strains][shell_dofs_per_node] = {};
  strain_transform(m, T);
  for (int i = 0; i < shell_strains; ++i)
    for (int j = 0; j < shell_strains; ++j)
      for (int c = 0; c < shell_dofs_per_node; ++c) out[i][c] += T[i][j] * B[j][c];
  for (int i = 0; i < shell_strains; ++i)
    for (int c = 0; c < shell_dofs_per_node; ++c) B[i][c] = out[i][c];
}

/// scale T^T R: resultants of the surface frame to those conjugate to the mesh-coordinate
/// strains (scale = m.area per unit mesh area; 1 per unit surface area).
inline void resultants_to_mesh(const ShellMetric& m, const double* R, double scale,
                               double (&out)[shell_strains]) {
  double T[shell_strains][shell_strains];
  strain_transform(m, T);
  for (int j = 0; j < shell_strains; ++j) {
    out[j] = 0;
    for (int i = 0; i < shell_strains; ++i) out[j] += T[i][j] * R[i];
    out[j] *= scale;
  }
}

}  // namespace efg
