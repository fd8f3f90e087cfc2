// The orientation of a rigid body in 3D (plain functions, no Trilinos): the rotation R that takes
// the body's frame (the scene's axes at the start) to the world's, row major. A finite 3D
// rotation does not add up as angles do: it is updated by the exponential map of the step's
// rotation vector, R <- exp(dt omega) R (Rodrigues' formula, e.g. Simo & Wong, IJNME 31, 1991,
// 19-52), and re-orthonormalized so that round-off does not accumulate over many steps.
#pragma once

#include <array>
#include <cmath>

namespace efg::contact {

using Orientation = std::array<double, 9>;

inline Orientation identity_orientation() {
  return {1, 0, 0, 0, 1, 0, 0, 0, 1};
}

/// out = R v (body to world).
inline void to_world(const Orientation& R, const double* v, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
}

/// out = R^T v (world to body).
inline void to_body(const Orientation& R, const double* v, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = R[i] * v[0] + R[3 + i] * v[1] + R[6 + i] * v[2];
}

/// exp(w) R: R turned by the rotation vector w (world axes). Rodrigues' rotation of each column,
/// then Gram-Schmidt on the columns.
inline Orientation turned(const Orientation& R, const double* w) {
  const double angle = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  Orientation out = R;
  if (angle == 0.0) return out;
  const double n[3] = {w[0] / angle, w[1] / angle, w[2] / angle};
  const double c = std::cos(angle), s = std::sin(angle);
  double col[3][3];
  for (int j = 0; j < 3; ++j) {
    const double v[3] = {R[j], R[3 + j], R[6 + j]};
    const double nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
    const double nxv[3] = {n[1] * v[2] - n[2] * v[1], n[2] * v[0] - n[0] * v[2],
                           n[0] * v[1] - n[1] * v[0]};
    for (int i = 0; i < 3; ++i) col[j][i] = c * v[i] + s * nxv[i] + (1 - c) * nv * n[i];
  }
  const auto normalize = [](double* v) {
    const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i) v[i] /= l;
  };
  normalize(col[0]);
  const double d = col[0][0] * col[1][0] + col[0][1] * col[1][1] + col[0][2] * col[1][2];
  for (int i = 0; i < 3; ++i) col[1][i] -= d * col[0][i];
  normalize(col[1]);
  col[2][0] = col[0][1] * col[1][2] - col[0][2] * col[1][1];
  col[2][1] = col[0][2] * col[1][0] - col[0][0] * col[1][2];
  col[2][2] = col[0][0] * col[1][1] - col[0][1] * col[1][0];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = col[j][i];
  return out;
}

/// L = R J R^T omega for the inertia tensor J about the centre in the body's axes (3 x 3, row
/// major; principal moments on its diagonal for the analytic shapes, a full tensor for bodies of
/// mesh cells): the angular momentum of a body turning at omega (world); with `inverse`,
/// omega = R J^-1 R^T L instead (J^-1 by cofactors: J is symmetric positive definite).
inline void inertia_times(const Orientation& R, const double* J, const double* v, double* out,
                          bool inverse = false) {
  double b[3], c[3];
  to_body(R, v, b);
  if (!inverse) {
    for (int i = 0; i < 3; ++i) c[i] = J[3 * i] * b[0] + J[3 * i + 1] * b[1] + J[3 * i + 2] * b[2];
  } else {
    const double co[9] = {
        J[4] * J[8] - J[5] * J[7], J[2] * J[7] - J[1] * J[8], J[1] * J[5] - J[2] * J[4],
        J[5] * J[6] - J[3] * J[8], J[0] * J[8] - J[2] * J[6], J[2] * J[3] - J[0] * J[5],
        J[3] * J[7] - J[4] * J[6], J[1] * J[6] - J[0] * J[7], J[0] * J[4] - J[1] * J[3]};
    const double det = J[0] * co[0] + J[1] * co[3] + J[2] * co[6];
    for (int i = 0; i < 3; ++i)
      c[i] = (co[3 * i] * b[0] + co[3 * i + 1] * b[1] + co[3 * i + 2] * b[2]) / det;
  }
  to_world(R, c, out);
}

}  // namespace efg::contact
