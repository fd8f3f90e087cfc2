#include "shells/FiniteRotation.hpp"

#include <Sacado.hpp>

#include <cmath>

namespace efg {
namespace {

void axpy(double s, const Vec3& x, Vec3& y) {
  for (int i = 0; i < 3; ++i) y[static_cast<std::size_t>(i)] += s * x[static_cast<std::size_t>(i)];
}

// cos r, sin r / r and (1 - cos r) / r^2 as functions of r^2: smooth at r = 0 (their series
// below r^2 = 1e-4, truncation below 1e-20), so that their derivatives are too.
template <class T>
void rotation_coefficients(const T& r2, T& c, T& s, T& h) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (Sacado::ScalarValue<T>::eval(r2) < 1e-4) {
    c = 1.0 - r2 / 2.0 + r2 * r2 / 24.0 - r2 * r2 * r2 / 720.0;
    s = 1.0 - r2 / 6.0 + r2 * r2 / 120.0 - r2 * r2 * r2 / 5040.0;
    h = 0.5 - r2 / 24.0 + r2 * r2 / 720.0 - r2 * r2 * r2 / 40320.0;
    return;
  }
  const T r = sqrt(r2);
  c = cos(r);
  s = sin(r) / r;
  h = (1.0 - c) / r2;
}

}  // namespace

NodeDirector node_director(const ShellFrame& frame, double a, double b) {
  // d(a, b) on nested forward AD numbers: the value, gradient and Hessian in one pass.
  using Inner = Sacado::Fad::SFad<double, 2>;
  using Outer = Sacado::Fad::SFad<Inner, 2>;
  const Outer A(2, 0, Inner(2, 0, a)), B(2, 1, Inner(2, 1, b));
  Outer c, s, h;
  rotation_coefficients<Outer>(A * A + B * B, c, s, h);
  NodeDirector out;
  for (std::size_t i = 0; i < 3; ++i) {
    const Outer d = c * frame.t3[i] + s * (B * frame.t1[i] - A * frame.t2[i]);
    out.d[i] = d.val().val();
    for (int p = 0; p < 2; ++p) {
      out.T[p][i] = d.dx(p).val();
      for (int q = 0; q < 2; ++q) out.S[p][q][i] = d.dx(p).dx(q);
    }
  }
  return out;
}

void rotate_frame(ShellFrame& frame, double a, double b) {
  Vec3 w{};
  axpy(a, frame.t1, w);
  axpy(b, frame.t2, w);
  double c, s, h;
  rotation_coefficients(dot(w, w), c, s, h);
  // Rodrigues: v' = cos r v + (sin r / r) w x v + ((1 - cos r) / r^2) (w . v) w
  const auto rotate = [&](const Vec3& v) {
    Vec3 out{};
    axpy(c, v, out);
    axpy(s, cross(w, v), out);
    axpy(h * dot(w, v), w, out);
    return out;
  };
  Vec3 t3 = rotate(frame.t3), t1 = rotate(frame.t1);
  // Round-off of many updates is removed, so that the frame stays orthonormal.
  axpy(1.0 / std::sqrt(dot(t3, t3)) - 1.0, t3, t3);
  axpy(-dot(t1, t3), t3, t1);
  axpy(1.0 / std::sqrt(dot(t1, t1)) - 1.0, t1, t1);
  frame = {t1, cross(t3, t1), t3};
}

namespace {

/// t3 normalized, t1 made orthogonal to it and normalized, t2 = t3 x t1.
ShellFrame orthonormal(ShellFrame f) {
  axpy(1.0 / std::sqrt(dot(f.t3, f.t3)) - 1.0, f.t3, f.t3);
  axpy(-dot(f.t1, f.t3), f.t3, f.t1);
  axpy(1.0 / std::sqrt(dot(f.t1, f.t1)) - 1.0, f.t1, f.t1);
  f.t2 = cross(f.t3, f.t1);
  return f;
}

}  // namespace

void frame_rotation(const ShellFrame& from, const ShellFrame& now, double& rx, double& ry) {
  const auto A = orthonormal(from), B = orthonormal(now);
  // R = sum_i B_i A_i^T maps A's vectors onto B's
  double R[3][3] = {};
  for (const auto& [a, b] : {std::pair{A.t1, B.t1}, {A.t2, B.t2}, {A.t3, B.t3}})
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) R[j][k] += b[j] * a[k];
  const double cosine = std::max(-1.0, std::min(1.0, 0.5 * (R[0][0] + R[1][1] + R[2][2] - 1)));
  Vec3 w = {R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]};  // 2 sin(angle) axis
  const double sine = std::sqrt(dot(w, w)) / 2;
  const double angle = std::atan2(sine, cosine);  // accurate at 0 and at pi, unlike acos
  if (angle < 0.5 * M_PI) {
    // w / (2 sin) is the axis; angle / sin -> 1 as the angle vanishes
    const double scale = sine > 0 ? angle / (2 * sine) : 0.5;
    for (auto& v : w) v *= scale;
  } else {
    // near pi the symmetric part tells the axis: (R + R^T) / 2 - cos I = (1 - cos) n n^T, whose
    // column of the largest diagonal entry is along n; w's sign (what is left of it) orients it
    std::size_t k = 0;
    for (std::size_t j = 1; j < 3; ++j)
      if (R[j][j] > R[k][k]) k = j;
    Vec3 n = {0.5 * (R[0][k] + R[k][0]), 0.5 * (R[1][k] + R[k][1]), 0.5 * (R[2][k] + R[k][2])};
    n[k] = R[k][k] - cosine;
    const double length = std::sqrt(dot(n, n));
    for (auto& v : n) v /= length;
    if (dot(n, w) < 0)
      for (auto& v : n) v = -v;
    for (std::size_t j = 0; j < 3; ++j) w[j] = angle * n[j];
  }
  rx = dot(w, A.t1);
  ry = dot(w, A.t2);
}

ShellPointGeometry reference_geometry() {
  ShellPointGeometry G;
  G.F[0] = G.f[0] = {1, 0, 0};
  G.F[1] = G.f[1] = {0, 1, 0};
  return G;
}

void add_to_geometry(const ShellNodeAtPoint& n, ShellPointGeometry& G) {
  for (std::size_t a = 0; a < 2; ++a) {
    axpy(n.b[a], n.u, G.F[a]);
    axpy(n.b[a], n.director.d, G.D[a]);
    axpy(n.g[a], n.u, G.f[a]);
  }
  axpy(n.phi, n.director.d, G.d);
}

void finite_rotation_strains(const ShellPointGeometry& G, double (&e)[shell_strains]) {
  e[0] = 0.5 * (dot(G.F[0], G.F[0]) - 1);
  e[1] = 0.5 * (dot(G.F[1], G.F[1]) - 1);
  e[2] = dot(G.F[0], G.F[1]);
  e[3] = dot(G.F[0], G.D[0]);
  e[4] = dot(G.F[1], G.D[1]);
  e[5] = dot(G.F[0], G.D[1]) + dot(G.F[1], G.D[0]);
  e[6] = dot(G.f[0], G.d);
  e[7] = dot(G.f[1], G.d);
}

void finite_rotation_rows(const ShellPointGeometry& G, const ShellNodeAtPoint& n,
                          double (&B)[shell_strains][shell_dofs_per_node]) {
  const double* b = n.b;
  const double* g = n.g;
  for (std::size_t j = 0; j < 3; ++j) {
    B[0][j] = G.F[0][j] * b[0];
    B[1][j] = G.F[1][j] * b[1];
    B[2][j] = G.F[1][j] * b[0] + G.F[0][j] * b[1];
    B[3][j] = G.D[0][j] * b[0];
    B[4][j] = G.D[1][j] * b[1];
    B[5][j] = G.D[1][j] * b[0] + G.D[0][j] * b[1];
    B[6][j] = G.d[j] * g[0];
    B[7][j] = G.d[j] * g[1];
  }
  for (std::size_t p = 0; p < 2; ++p) {
    const Vec3& T = n.director.T[p];
    const std::size_t c = shell_rx + p;
    B[0][c] = B[1][c] = B[2][c] = 0;
    B[3][c] = b[0] * dot(G.F[0], T);
    B[4][c] = b[1] * dot(G.F[1], T);
    B[5][c] = b[1] * dot(G.F[0], T) + b[0] * dot(G.F[1], T);
    B[6][c] = n.phi * dot(G.f[0], T);
    B[7][c] = n.phi * dot(G.f[1], T);
  }
}

void finite_rotation_geometric(const ShellPointGeometry& G, const double (&R)[shell_strains],
                               const ShellNodeAtPoint& m, const ShellNodeAtPoint& n, bool same,
                               double (&K)[shell_dofs_per_node][shell_dofs_per_node]) {
  for (auto& row : K)
    for (auto& v : row) v = 0;
  const double *bm = m.b, *bn = n.b;
  // membrane: e_0..2 are quadratic in the translations alone
  const double uu =
      R[0] * bm[0] * bn[0] + R[1] * bm[1] * bn[1] + R[2] * (bm[0] * bn[1] + bm[1] * bn[0]);
  // bending and shear couple a translation of one particle with a director of the other
  const auto coupling = [&](const ShellNodeAtPoint& x, const ShellNodeAtPoint& y) {
    return R[3] * x.b[0] * y.b[0] + R[4] * x.b[1] * y.b[1] +
           R[5] * (x.b[0] * y.b[1] + x.b[1] * y.b[0]) + R[6] * x.g[0] * y.phi +
           R[7] * x.g[1] * y.phi;
  };
  const double mn = coupling(m, n), nm = coupling(n, m);
  for (std::size_t j = 0; j < 3; ++j) {
    K[j][j] = uu;
    for (std::size_t p = 0; p < 2; ++p) {
      K[j][shell_rx + p] = mn * n.director.T[p][j];
      K[shell_rx + p][j] = nm * m.director.T[p][j];
    }
  }
  if (!same) return;
  // a director's own curvature (d2 d / dw2): its conjugate force h times S
  Vec3 h{};
  axpy(R[3] * bm[0] + R[5] * bm[1], G.F[0], h);
  axpy(R[4] * bm[1] + R[5] * bm[0], G.F[1], h);
  axpy(R[6] * m.phi, G.f[0], h);
  axpy(R[7] * m.phi, G.f[1], h);
  for (std::size_t p = 0; p < 2; ++p)
    for (std::size_t q = 0; q < 2; ++q) K[shell_rx + p][shell_rx + q] = dot(h, m.director.S[p][q]);
}

void finite_rotation_edge_reaction(const ShellPointGeometry& G, const double (&R)[shell_strains],
                                   const double (&normal)[2], Vec3& t, Vec3& m) {
  const double n0 = normal[0], n1 = normal[1];
  t = {0, 0, 0};
  m = {0, 0, 0};
  // t = n_a dW/dF_a (the shear's f_a is F_a at an edge point), m = n_a dW/dD_a
  axpy(n0 * R[0] + n1 * R[2], G.F[0], t);
  axpy(n1 * R[1] + n0 * R[2], G.F[1], t);
  axpy(n0 * R[3] + n1 * R[5], G.D[0], t);
  axpy(n1 * R[4] + n0 * R[5], G.D[1], t);
  axpy(n0 * R[6] + n1 * R[7], G.d, t);
  axpy(n0 * R[3] + n1 * R[5], G.F[0], m);
  axpy(n1 * R[4] + n0 * R[5], G.F[1], m);
}

void finite_rotation_edge_reaction_change(const ShellPointGeometry& G,
                                          const double (&R)[shell_strains],
                                          const double (&dR)[shell_strains],
                                          const double (&normal)[2], const ShellNodeAtPoint& n,
                                          int c, Vec3& dt, Vec3& dm) {
  // the resultants' change at fixed kinematics
  finite_rotation_edge_reaction(G, dR, normal, dt, dm);
  const double n0 = normal[0], n1 = normal[1];
  const double* g = n.g;
  if (c < shell_rx) {  // dF_a = g_a e_c
    dt[static_cast<std::size_t>(c)] +=
        n0 * (R[0] * g[0] + R[2] * g[1]) + n1 * (R[1] * g[1] + R[2] * g[0]);
    dm[static_cast<std::size_t>(c)] +=
        n0 * (R[3] * g[0] + R[5] * g[1]) + n1 * (R[4] * g[1] + R[5] * g[0]);
    return;
  }
  // dD_a = g_a T, dd = phi T
  const Vec3& T = n.director.T[c - shell_rx];
  axpy(n0 * (R[3] * g[0] + R[5] * g[1] + R[6] * n.phi) +
           n1 * (R[4] * g[1] + R[5] * g[0] + R[7] * n.phi),
       T, dt);
}

}  // namespace efg
