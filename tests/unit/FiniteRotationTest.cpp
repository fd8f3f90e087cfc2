// The finite-rotation kinematics of shells (src/shells/FiniteRotation.hpp) against hand values
// and central differences: the director map and its derivatives, the frame update, the strain
// rows, the geometric stiffness and the edge reaction's change are the derivatives of the
// functions they differentiate; the strains of an arc and of a rigid rotation are the exact ones.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shells/FiniteRotation.hpp"

namespace efg {
namespace {

constexpr int nd = shell_dofs_per_node;
constexpr double pi = 3.14159265358979323846;

// A frame turned away from the reference (two accepted rotations).
ShellFrame turned_frame() {
  ShellFrame f;
  rotate_frame(f, 0.4, -1.1);
  rotate_frame(f, -2.2, 0.3);
  return f;
}

TEST(FiniteRotation, DirectorIsTheExponentialMapAndItsDerivativesAreExact) {
  // reference frame, rotation b about E2 by 1.2: d = (sin 1.2, 0, cos 1.2) (hand value)
  const auto about_y = node_director(ShellFrame{}, 0.0, 1.2);
  EXPECT_NEAR(about_y.d[0], std::sin(1.2), 1e-15);
  EXPECT_NEAR(about_y.d[1], 0.0, 1e-15);
  EXPECT_NEAR(about_y.d[2], std::cos(1.2), 1e-15);
  // rotation a about E1 by 0.5: d = (0, -sin 0.5, cos 0.5)
  const auto about_x = node_director(ShellFrame{}, 0.5, 0.0);
  EXPECT_NEAR(about_x.d[1], -std::sin(0.5), 1e-15);
  // small rotations: the linear shell's (theta_y, -theta_x, 1)
  const auto zero = node_director(ShellFrame{}, 0.0, 0.0);
  EXPECT_NEAR(zero.T[0][1], -1.0, 1e-15);
  EXPECT_NEAR(zero.T[1][0], 1.0, 1e-15);
  const ShellFrame frames[] = {ShellFrame{}, turned_frame()};
  const double at[][2] = {{0.0, 0.0}, {3e-3, -5e-3}, {0.7, -1.9}, {-2.5, 1.6}};
  const double h = 1e-5;
  for (const auto& f : frames)
    for (const auto& w : at) {
      const auto n = node_director(f, w[0], w[1]);
      EXPECT_NEAR(dot(n.d, n.d), 1.0, 1e-14);
      for (int p = 0; p < 2; ++p) {
        const double e[2] = {p == 0 ? h : 0.0, p == 1 ? h : 0.0};
        const auto plus = node_director(f, w[0] + e[0], w[1] + e[1]);
        const auto minus = node_director(f, w[0] - e[0], w[1] - e[1]);
        for (std::size_t i = 0; i < 3; ++i) {
          EXPECT_NEAR(n.T[p][i], (plus.d[i] - minus.d[i]) / (2 * h), 1e-9);
          for (int q = 0; q < 2; ++q)
            EXPECT_NEAR(n.S[p][q][i], (plus.T[q][i] - minus.T[q][i]) / (2 * h), 1e-9);
        }
      }
    }
}

TEST(FiniteRotation, PhysicalRotationRecoversTheRotationVectorInTheFrame) {
  // The output rotation (frame_rotation) of a frame turned by w = a t1 + b t2 from any frame is
  // (a, b) itself while |w| <= pi (the exponential map's inverse), at pi too, where the two
  // directors are antiparallel and tell no axis.
  const ShellFrame frames[] = {ShellFrame{}, turned_frame()};
  const double at[][2] = {{0.3, -0.2}, {-1.1, 2.0}, {1e-7, 3e-8},
                          {2.2, 1.9},  {0.0, M_PI}, {-M_PI * 0.6, M_PI * 0.8},
                          {3.0, 0.1}};
  for (const auto& f : frames)
    for (const auto& w : at) {
      ShellFrame now = f;
      rotate_frame(now, w[0], w[1]);
      double rx = 0, ry = 0;
      frame_rotation(f, now, rx, ry);
      const double sign = std::hypot(w[0], w[1]) > M_PI - 1e-9 && rx * w[0] + ry * w[1] < 0
                              ? -1.0  // at pi, -w is the same rotation
                              : 1.0;
      EXPECT_NEAR(sign * rx, w[0], 1e-9) << w[0] << ", " << w[1];
      EXPECT_NEAR(sign * ry, w[1], 1e-9) << w[0] << ", " << w[1];
    }
  // the flat form: E3 turned by 0.4 about x gives rx = 0.4
  ShellFrame now;
  rotate_frame(now, 0.4, 0.0);
  double rx = 0, ry = 0;
  frame_rotation(ShellFrame{}, now, rx, ry);
  EXPECT_NEAR(rx, 0.4, 1e-14);
  EXPECT_NEAR(ry, 0.0, 1e-14);
}

TEST(FiniteRotation, FrameUpdateCarriesTheDirectorAndStaysOrthonormal) {
  ShellFrame f = turned_frame();
  const auto expected = node_director(f, -0.8, 2.9).d;
  rotate_frame(f, -0.8, 2.9);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(f.t3[i], expected[i], 1e-14);
  EXPECT_NEAR(dot(f.t1, f.t1), 1.0, 1e-15);
  EXPECT_NEAR(dot(f.t2, f.t2), 1.0, 1e-15);
  EXPECT_NEAR(dot(f.t1, f.t3), 0.0, 1e-15);
  EXPECT_NEAR(dot(f.t2, f.t3), 0.0, 1e-15);
  // right-handed: t1 x t2 = t3
  EXPECT_NEAR(f.t1[0] * f.t2[1] - f.t1[1] * f.t2[0], f.t3[2], 1e-15);
  // a full turn about t2 in 8 steps returns the frame
  ShellFrame g;
  for (int k = 0; k < 8; ++k) rotate_frame(g, 0.0, pi / 4);
  EXPECT_NEAR(g.t3[2], 1.0, 1e-14);
  EXPECT_NEAR(g.t1[0], 1.0, 1e-14);
}

// A point of three particles with arbitrary gradients, values, translations and rotations.
struct ThreePoint {
  std::vector<double> b = {0.8, -0.3, -0.5, 0.9, -0.3, -0.6};
  std::vector<double> g = {0.7, -0.2, -0.4, 1.1, -0.3, -0.9};
  std::vector<double> phi = {0.3, 0.5, 0.2};
  std::vector<ShellFrame> frames = {ShellFrame{}, turned_frame(), ShellFrame{}};
  std::vector<double> q = {0.1, -0.2, 0.3,  0.2,  -0.4, -0.1, 0.05, 0.2,
                           0.6, 1.3,  0.15, -0.1, -0.2, 0.4,  -0.7};

  FiniteRotationPoint point(const std::vector<double>& dofs) const {
    FiniteRotationPoint p;
    p.geometry = reference_geometry();
    for (std::size_t a = 0; a < 3; ++a) {
      const double* x = &dofs[a * nd];
      p.nodes.push_back(
          {&b[2 * a], &g[2 * a], phi[a], {x[0], x[1], x[2]}, node_director(frames[a], x[3], x[4])});
      add_to_geometry(p.nodes.back(), p.geometry);
    }
    return p;
  }
  void strains(const std::vector<double>& dofs, double (&e)[shell_strains]) const {
    finite_rotation_strains(point(dofs).geometry, e);
  }
};

TEST(FiniteRotation, StrainRowsAreTheDerivativesOfTheStrains) {
  const ThreePoint t;
  const auto p = t.point(t.q);
  const double h = 1e-6;
  for (std::size_t a = 0; a < 3; ++a) {
    double B[shell_strains][nd];
    finite_rotation_rows(p.geometry, p.nodes[a], B);
    for (std::size_t c = 0; c < nd; ++c) {
      auto plus = t.q, minus = t.q;
      plus[a * nd + c] += h;
      minus[a * nd + c] -= h;
      double ep[shell_strains], em[shell_strains];
      t.strains(plus, ep);
      t.strains(minus, em);
      for (int k = 0; k < shell_strains; ++k)
        EXPECT_NEAR(B[k][c], (ep[k] - em[k]) / (2 * h), 1e-8) << a << " " << c << " " << k;
    }
  }
}

TEST(FiniteRotation, GeometricStiffnessIsTheDerivativeOfTheRowsTimesFixedResultants) {
  const ThreePoint t;
  const double R[shell_strains] = {1.3, -0.7, 0.4, 2.1, -1.5, 0.8, 0.6, -0.9};
  const auto force = [&](const std::vector<double>& dofs, std::size_t a, std::size_t c) {
    const auto p = t.point(dofs);
    double B[shell_strains][nd];
    finite_rotation_rows(p.geometry, p.nodes[a], B);
    double f = 0;
    for (int k = 0; k < shell_strains; ++k) f += R[k] * B[k][c];
    return f;
  };
  const auto p = t.point(t.q);
  const double h = 1e-6;
  for (std::size_t a = 0; a < 3; ++a)
    for (std::size_t b = 0; b < 3; ++b) {
      double G[nd][nd];
      finite_rotation_geometric(p.geometry, R, p.nodes[a], p.nodes[b], a == b, G);
      for (std::size_t e = 0; e < nd; ++e) {
        auto plus = t.q, minus = t.q;
        plus[b * nd + e] += h;
        minus[b * nd + e] -= h;
        for (std::size_t c = 0; c < nd; ++c)
          EXPECT_NEAR(G[c][e], (force(plus, a, c) - force(minus, a, c)) / (2 * h), 1e-7)
              << a << " " << c << " / " << b << " " << e;
      }
    }
}

TEST(FiniteRotation, EdgeReactionChangeIsItsDerivative) {
  // An edge point (b = g) whose resultants follow a linear law R = C e of the strains.
  ThreePoint t;
  t.b = t.g;
  double C[shell_strains][shell_strains];
  for (int i = 0; i < shell_strains; ++i)
    for (int j = 0; j < shell_strains; ++j)
      C[i][j] = (i == j ? 2.0 : 0.0) + 0.1 * std::sin(i + 3 * j);
  const double normal[2] = {0.6, -0.8};
  const auto reaction = [&](const std::vector<double>& dofs, Vec3& tr, Vec3& m) {
    const auto p = t.point(dofs);
    double e[shell_strains], R[shell_strains] = {};
    finite_rotation_strains(p.geometry, e);
    for (int i = 0; i < shell_strains; ++i)
      for (int j = 0; j < shell_strains; ++j) R[i] += C[i][j] * e[j];
    finite_rotation_edge_reaction(p.geometry, R, normal, tr, m);
    return R[0];
  };
  const auto p = t.point(t.q);
  double e[shell_strains], R[shell_strains] = {};
  finite_rotation_strains(p.geometry, e);
  for (int i = 0; i < shell_strains; ++i)
    for (int j = 0; j < shell_strains; ++j) R[i] += C[i][j] * e[j];
  const double h = 1e-6;
  for (std::size_t b = 0; b < 3; ++b) {
    double B[shell_strains][nd];
    finite_rotation_rows(p.geometry, p.nodes[b], B);
    for (int c = 0; c < nd; ++c) {
      double dR[shell_strains] = {};
      for (int i = 0; i < shell_strains; ++i)
        for (int j = 0; j < shell_strains; ++j) dR[i] += C[i][j] * B[j][c];
      Vec3 dt, dm, tp, mp, tm, mm;
      finite_rotation_edge_reaction_change(p.geometry, R, dR, normal, p.nodes[b], c, dt, dm);
      auto plus = t.q, minus = t.q;
      plus[b * nd + static_cast<std::size_t>(c)] += h;
      minus[b * nd + static_cast<std::size_t>(c)] -= h;
      reaction(plus, tp, mp);
      reaction(minus, tm, mm);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(dt[i], (tp[i] - tm[i]) / (2 * h), 1e-7) << b << " " << c;
        EXPECT_NEAR(dm[i], (mp[i] - mm[i]) / (2 * h), 1e-7) << b << " " << c;
      }
    }
  }
}

TEST(FiniteRotation, ArcAndRigidRotationHaveTheExactStrains) {
  // Pure bending into an arc of curvature k about E2 at X = s: x = (sin ks / k, 0,
  // (1 - cos ks) / k), director (-sin ks, 0, cos ks) ... expressed through the point
  // quantities directly: F1 = (cos ks, 0, sin ks), D1 = k d(d)/d(ks), F2 = E2.
  const double k = 2 * pi / 3, s = 2.2;
  ShellPointGeometry arc = reference_geometry();
  arc.F[0] = arc.f[0] = {std::cos(k * s), 0, std::sin(k * s)};
  arc.d = {-std::sin(k * s), 0, std::cos(k * s)};
  arc.D[0] = {-k * std::cos(k * s), 0, -k * std::sin(k * s)};
  double e[shell_strains];
  finite_rotation_strains(arc, e);
  // the director turns towards -x as the surface curves up: kappa_xx = F1 . D1 = -k
  const double expected[shell_strains] = {0, 0, 0, -k, 0, 0, 0, 0};
  for (int i = 0; i < shell_strains; ++i) EXPECT_NEAR(e[i], expected[i], 1e-14) << i;
  // A rigid rotation (any size) of a flat state strains nothing: F_a = Q E_a, d = Q E3.
  ShellFrame Q;
  rotate_frame(Q, 1.7, -2.4);
  ShellPointGeometry rigid = reference_geometry();
  rigid.F[0] = rigid.f[0] = Q.t1;
  rigid.F[1] = rigid.f[1] = Q.t2;
  rigid.d = Q.t3;
  finite_rotation_strains(rigid, e);
  for (double v : e) EXPECT_NEAR(v, 0.0, 1e-15);
}

}  // namespace
}  // namespace efg
