// The metric of curved shell references (src/shells/ShellMetric.hpp) against the tensor
// transformation it stands for: covariant components E_ab = A_a . E A_b (and gamma_a = A_a . g)
// of a tangent tensor E given in 3D must come out as the frame's E_(alpha beta) = t_alpha . E
// t_beta, for a general map (tangents neither unit nor orthogonal) and a frame whose t1 is not
// along A1; the resultants it returns are the work conjugates (R . T e = T^T R . e).
#include <gtest/gtest.h>

#include <cmath>

#include "shells/ShellMetric.hpp"

namespace efg {
namespace {

Vec3 combine(double a, const Vec3& x, double b, const Vec3& y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]};
}

struct Setup {
  Vec3 A[2];
  ShellFrame frame;
};

// A tangent plane spanned by two skew vectors, the frame turned by 0.7 rad within it.
Setup general_setup() {
  Setup s;
  s.A[0] = {1.3, -0.4, 0.5};
  s.A[1] = {0.2, 0.9, 0.6};
  Vec3 n = cross(s.A[0], s.A[1]);
  const double ln = std::sqrt(dot(n, n));
  for (auto& v : n) v /= ln;
  Vec3 e1 = s.A[0];
  const double l1 = std::sqrt(dot(e1, e1));
  for (auto& v : e1) v /= l1;
  const Vec3 e2 = cross(n, e1);
  s.frame.t1 = combine(std::cos(0.7), e1, std::sin(0.7), e2);
  s.frame.t2 = combine(-std::sin(0.7), e1, std::cos(0.7), e2);
  s.frame.t3 = n;
  return s;
}

/// x . E y for the symmetric tangent tensor E = sum of p q^T + q p^T (p, q in the plane).
double form(const Vec3& p, const Vec3& q, const Vec3& x, const Vec3& y) {
  return dot(x, p) * dot(q, y) + dot(x, q) * dot(p, y);
}

TEST(ShellMetric, StrainsOfTheMeshCoordinatesBecomeTheFramesComponents) {
  const auto s = general_setup();
  const auto m = shell_metric(s.A, s.frame);
  // area |A1 x A2|
  const Vec3 n = cross(s.A[0], s.A[1]);
  EXPECT_NEAR(m.area, std::sqrt(dot(n, n)), 1e-14);
  // two tensors (membrane, bending) and a shear vector, in the plane
  const Vec3 p = combine(0.3, s.A[0], -1.1, s.A[1]), q = combine(0.8, s.A[0], 0.4, s.A[1]);
  const Vec3 r = combine(-0.6, s.A[0], 0.9, s.A[1]), u = combine(0.1, s.A[0], 0.7, s.A[1]);
  const Vec3 g = combine(0.5, s.A[0], -0.2, s.A[1]);
  double e[shell_strains] = {form(p, q, s.A[0], s.A[0]),
                             form(p, q, s.A[1], s.A[1]),
                             2 * form(p, q, s.A[0], s.A[1]),
                             form(r, u, s.A[0], s.A[0]),
                             form(r, u, s.A[1], s.A[1]),
                             2 * form(r, u, s.A[0], s.A[1]),
                             dot(s.A[0], g),
                             dot(s.A[1], g)};
  const double cov[shell_strains] = {e[0], e[1], e[2], e[3], e[4], e[5], e[6], e[7]};
  strains_to_surface(m, e);
  const auto &t1 = s.frame.t1, &t2 = s.frame.t2;
  const double expected[shell_strains] = {
      form(p, q, t1, t1), form(p, q, t2, t2), 2 * form(p, q, t1, t2),
      form(r, u, t1, t1), form(r, u, t2, t2), 2 * form(r, u, t1, t2),
      dot(t1, g),         dot(t2, g)};
  for (int i = 0; i < shell_strains; ++i) EXPECT_NEAR(e[i], expected[i], 1e-13) << "strain " << i;

  // rows: B of a dof mapped like the strains
  double B[shell_strains][shell_dofs_per_node] = {};
  for (int i = 0; i < shell_strains; ++i) B[i][i % shell_dofs_per_node] = cov[i];
  rows_to_surface(m, B);
  for (int i = 0; i < shell_strains; ++i) {
    double sum = 0;
    for (int c = 0; c < shell_dofs_per_node; ++c) sum += B[i][c];
    EXPECT_NEAR(sum, expected[i], 1e-13) << "row " << i;
  }

  // work conjugates: (T^T R) . e_cov = R . e_surface, times the scale
  const double R[shell_strains] = {1.0, -2.0, 0.5, 3.0, 0.25, -1.5, 0.75, 2.0};
  double Rm[shell_strains];
  resultants_to_mesh(m, R, 2.5, Rm);
  double work_mesh = 0, work_surface = 0;
  for (int i = 0; i < shell_strains; ++i) {
    work_mesh += Rm[i] * cov[i];
    work_surface += R[i] * expected[i];
  }
  EXPECT_NEAR(work_mesh, 2.5 * work_surface, 1e-12);
}

TEST(ShellMetric, AnIsometryIsTheIdentity) {
  ShellFrame frame;
  frame.t1 = {0, 0.6, 0.8};
  frame.t2 = {1, 0, 0};
  frame.t3 = cross(frame.t1, frame.t2);
  const Vec3 A[2] = {frame.t1, frame.t2};
  const auto m = shell_metric(A, frame);
  EXPECT_NEAR(m.area, 1, 1e-15);
  double e[shell_strains] = {1, 2, 3, 4, 5, 6, 7, 8};
  strains_to_surface(m, e);
  for (int i = 0; i < shell_strains; ++i) EXPECT_NEAR(e[i], i + 1, 1e-14);
}

}  // namespace
}  // namespace efg
