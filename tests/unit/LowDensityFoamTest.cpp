// The low-density foam (physics/materials/LowDensityFoam.hpp, the role of LS-DYNA *MAT_057) at
// one material point, against closed forms worked by hand (docs/foams.md):
//   F = diag(lambda_1, lambda_2, lambda_3) keeps the principal directions on the axes, R = I and
//   P = diag(T_1, T_2, T_3) with T_a = -f(1 - lambda_a) on loading, the nominal stress of the
//   curve; Cauchy sigma_1 = T_1 / (lambda_2 lambda_3); a direction at lambda = 1 carries nothing
//   whatever the others do (no coupling);
//   unloading below the largest strain m: T = -(HU + (1 - HU) (e / m)^SHAPE) f(e);
//   one cycle 0 -> m -> 0 dissipates D = (1 - HU) int_0^m (1 - (x / m)^SHAPE) f(x) dx, computed
//   here by Gauss-Legendre quadrature of that formula on the curve's linear pieces (3 points per
//   piece: exact for SHAPE = 2, a cubic), not by the law's closed form.
// The curve (nominal strain, nominal stress in MPa): (0, 0) (0.05, 0.1) (0.5, 0.15) (0.8, 1.0)
// (0.9, 3.0), slopes 2, 1/9, 17/6, 20 (and 20 beyond 0.9). By hand: f(0.02) = 0.04,
// f(0.3) = 0.1 + 0.25 / 9 = 0.127777..., f(0.6) = 0.15 + 0.1 x 17/6 = 0.433333...,
// f(0.85) = 2.0, f(0.95) = 4.0.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/LowDensityFoam.hpp"
#include "operators/MaterialTangent.hpp"

namespace efg::physics {
namespace {

constexpr int S = ldfoam_state::count;
const double x_[] = {0.0, 0.05, 0.5, 0.8, 0.9}, y_[] = {0.0, 0.1, 0.15, 1.0, 3.0};

LowDensityFoamParameters foam(double hu = 1.0, double shape = 1.0, double tc = 1e300) {
  LowDensityFoamParameters p;
  p.tension_modulus = 5.0;
  p.curve_points = 5;
  for (int i = 0; i < 5; ++i) p.curve_strain[i] = x_[i], p.curve_stress[i] = y_[i];
  p.hysteresis = hu, p.shape = shape, p.tension_cutoff = tc;
  p.stiffness = ldfoam_stiffness_bound(p);
  return p;
}

// The curve by hand (linear pieces, the last slope 20 beyond 0.9).
double hand_f(double e) {
  for (int i = 1; i < 5; ++i)
    if (e <= x_[i]) return y_[i - 1] + (e - x_[i - 1]) * (y_[i] - y_[i - 1]) / (x_[i] - x_[i - 1]);
  return 3.0 + 20.0 * (e - 0.9);
}

// D of one cycle to m (m <= 0.9), by 3-point Gauss-Legendre on each linear piece of f.
double hand_cycle_dissipation(double hu, double shape, double m) {
  const double g[] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  double sum = 0.0;
  for (int i = 1; i < 5 && x_[i - 1] < m; ++i) {
    const double a = x_[i - 1], b = std::fmin(x_[i], m);
    for (int k = 0; k < 3; ++k) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * g[k];
      sum += 0.5 * (b - a) * w[k] * (1.0 - std::pow(x / m, shape)) * hand_f(x);
    }
  }
  return (1.0 - hu) * sum;
}

struct Point {
  LowDensityFoamParameters p;
  double state[S];
  double P[3][3], cauchy[3][3];
  explicit Point(const LowDensityFoamParameters& law) : p(law) { ldfoam_initial_state(state); }
  void deform(const double (&F)[3][3]) {
    double H[3][3], next[S];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H[i][j] = F[i][j] - (i == j ? 1.0 : 0.0);
    ASSERT_TRUE(ldfoam_update<3>(p, H, state, P, next, cauchy));
    for (int k = 0; k < S; ++k) state[k] = next[k];
  }
  void stretch(double f1, double f2 = 1.0, double f3 = 1.0) {
    const double F[3][3] = {{f1, 0, 0}, {0, f2, 0}, {0, 0, f3}};
    deform(F);
  }
};

TEST(LowDensityFoam, HandValuesOfTheCurveAndTheBound) {
  const auto p = foam(0.2, 2.0);
  const double e[] = {0.02, 0.3, 0.6, 0.85, 0.95},
               s[] = {0.04, 0.1 + 0.25 / 9, 0.15 + 1.7 / 6, 2.0, 4.0};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(ldfoam_loading_stress(p, e[i]), s[i], 1e-14) << e[i];
  // K = max(E_t, f'_max (1 + (1 - HU) SHAPE)) = max(5, 20 x 2.6) = 52.
  EXPECT_NEAR(p.stiffness, 52.0, 1e-12);
}

TEST(LowDensityFoam, MonotonicCompressionFollowsTheCurveWithoutTransverseStress) {
  Point pt(foam(0.2, 2.0));
  const double check[] = {0.02, 0.3, 0.6, 0.85, 0.95};
  int next = 0;
  for (int k = 1; k <= 1900; ++k) {  // e = k / 2000 up to 0.95
    const double e = k * 5e-4;
    pt.stretch(1.0 - e);
    if (next < 5 && std::abs(e - check[next]) < 1e-12) {
      EXPECT_NEAR(pt.P[0][0], -hand_f(e), 1e-10) << e;
      EXPECT_NEAR(pt.cauchy[0][0], -hand_f(e), 1e-10) << e;  // lambda_2 = lambda_3 = 1
      ++next;
    }
    // No coupling: the free lateral directions stay unloaded (zero Poisson ratio).
    for (int i = 1; i < 3; ++i) EXPECT_NEAR(pt.cauchy[i][i], 0.0, 1e-12) << e;
    EXPECT_NEAR(pt.cauchy[0][1], 0.0, 1e-12);
  }
  EXPECT_EQ(next, 5);
  EXPECT_NEAR(pt.state[ldfoam_state::crush], 0.95, 1e-12);
}

TEST(LowDensityFoam, BiaxialCompressionIsTwoIndependentCurves) {
  // F = diag(0.4, 0.7, 1): T_1 = -f(0.6), T_2 = -f(0.3), sigma_1 = T_1 / 0.7, sigma_2 = T_2 / 0.4.
  Point pt(foam());
  for (int k = 1; k <= 100; ++k) pt.stretch(1.0 - 0.006 * k, 1.0 - 0.003 * k);
  EXPECT_NEAR(pt.P[0][0], -(0.15 + 1.7 / 6), 1e-10);
  EXPECT_NEAR(pt.P[1][1], -(0.1 + 0.25 / 9), 1e-10);
  EXPECT_NEAR(pt.cauchy[0][0], -(0.15 + 1.7 / 6) / 0.7, 1e-10);
  EXPECT_NEAR(pt.cauchy[1][1], -(0.1 + 0.25 / 9) / 0.4, 1e-10);
  EXPECT_NEAR(pt.cauchy[2][2], 0.0, 1e-12);
}

TEST(LowDensityFoam, UnloadingAndReloadingFollowTheHysteresisCurve) {
  const double hu = 0.2, shape = 2.0, m = 0.7;
  Point pt(foam(hu, shape));
  for (int k = 1; k <= 700; ++k) pt.stretch(1.0 - k * 1e-3);
  auto unload = [&](double e) { return -(hu + (1 - hu) * std::pow(e / m, shape)) * hand_f(e); };
  for (int k = 699; k >= 300; --k) {  // unload to e = 0.3
    pt.stretch(1.0 - k * 1e-3);
    if (k == 500) {
      EXPECT_NEAR(pt.P[0][0], unload(0.5), 1e-10);
    }
  }
  EXPECT_NEAR(pt.P[0][0], unload(0.3), 1e-10);
  for (int k = 301; k <= 850; ++k) {  // reload on the same curve, then on the loading curve
    pt.stretch(1.0 - k * 1e-3);
    if (k == 600) {
      EXPECT_NEAR(pt.P[0][0], unload(0.6), 1e-10);
    }
  }
  EXPECT_NEAR(pt.P[0][0], -2.0, 1e-10);
  EXPECT_NEAR(pt.state[ldfoam_state::crush], 0.85, 1e-12);
}

// Work sum of the trapezoid rule P_11 d lambda_1 along a path of axial stretches.
struct Cycle {
  double work = 0.0, stored = 0.0, dissipated = 0.0, largest_gap = 0.0;
};

Cycle run_cycle(const LowDensityFoamParameters& p, double m, int steps) {
  Point pt(p);
  Cycle c;
  double lambda = 1.0, T = 0.0;
  auto step = [&](double e) {
    pt.stretch(1.0 - e);
    c.work += 0.5 * (T + pt.P[0][0]) * ((1.0 - e) - lambda);
    lambda = 1.0 - e, T = pt.P[0][0];
    c.stored = pt.state[ldfoam_state::elastic_energy];
    c.dissipated = pt.state[ldfoam_state::dissipation];
    c.largest_gap = std::fmax(c.largest_gap, std::abs(c.stored + c.dissipated - c.work));
  };
  for (int k = 1; k <= steps; ++k) step(m * k / steps);
  for (int k = steps - 1; k >= 0; --k) step(m * k / steps);
  return c;
}

TEST(LowDensityFoam, LoadUnloadCycleDissipatesTheClosedFormHysteresisEnergy) {
  const double hu = 0.2, shape = 2.0, m = 0.7;
  const double D = hand_cycle_dissipation(hu, shape, m);
  const Cycle c = run_cycle(foam(hu, shape), m, 70000);  // steps of 1e-5
  // The work by the trapezoid rule on the law's stresses: the loading leg is exact (piecewise
  // linear, kinks on the grid), the unloading leg errs by h^2/12 int (g f)''.
  EXPECT_NEAR(c.work / D, 1.0, 1e-8) << "D = " << D << ", work = " << c.work;
  EXPECT_NEAR(c.dissipated / D, 1.0, 1e-12);
  EXPECT_NEAR(c.stored, 0.0, 1e-15);  // back at lambda = 1
  // With SHAPE = 1 too (the quadrature is then exact for a quadratic).
  const double D1 = hand_cycle_dissipation(0.5, 1.0, 0.85);
  const Cycle c1 = run_cycle(foam(0.5, 1.0), 0.85, 85000);
  EXPECT_NEAR(c1.work / D1, 1.0, 1e-8);
  EXPECT_NEAR(c1.dissipated / D1, 1.0, 1e-12);
}

TEST(LowDensityFoam, HysteresisOneIsElastic) {
  const Cycle c = run_cycle(foam(1.0, 3.0), 0.85, 2000);
  EXPECT_EQ(c.dissipated, 0.0);
  EXPECT_NEAR(c.work, 0.0, 1e-12);
  Point pt(foam(1.0, 3.0));
  for (int k = 1; k <= 80; ++k) pt.stretch(1.0 - k * 0.01);
  pt.stretch(0.7);  // unloaded to e = 0.3: on the loading curve
  EXPECT_NEAR(pt.P[0][0], -(0.1 + 0.25 / 9), 1e-12);
}

TEST(LowDensityFoam, EnergyAccountStoredPlusDissipatedEqualsWork) {
  // psi + D against the trapezoid work at every step of a cycle to 0.85 (e = k / 1000), and at
  // the peak against the closed-form work int_0^0.85 f = 0.0025 + 0.05625 + 0.1725 + 0.075 =
  // 0.30625 (the pieces' trapezoids by hand).
  const auto p = foam(0.3, 1.5);
  Point pt(p);
  double work = 0.0, lambda = 1.0, T = 0.0;
  for (int k = 1; k <= 850; ++k) {
    pt.stretch(1.0 - k * 1e-3);
    work += 0.5 * (T + pt.P[0][0]) * ((1.0 - k * 1e-3) - lambda);
    lambda = 1.0 - k * 1e-3, T = pt.P[0][0];
  }
  const double total = pt.state[ldfoam_state::elastic_energy] + pt.state[ldfoam_state::dissipation];
  EXPECT_NEAR(total, 0.30625, 1e-12);
  EXPECT_NEAR(work, 0.30625, 1e-12);  // trapezoid exact on the piecewise linear loading
  double gap = 0.0;
  for (int k = 849; k >= 0; --k) {
    pt.stretch(1.0 - k * 1e-3);
    work += 0.5 * (T + pt.P[0][0]) * ((1.0 - k * 1e-3) - lambda);
    lambda = 1.0 - k * 1e-3, T = pt.P[0][0];
    gap = std::fmax(gap, std::abs(pt.state[ldfoam_state::elastic_energy] +
                                  pt.state[ldfoam_state::dissipation] - work));
  }
  // Unloading: the trapezoid's error is at most h^2 / 12 int |(g f)''| de (f'' = 0 on the
  // pieces, whose kinks lie on the grid), with (g f)'' = g'' f + 2 g' f' and, by hand,
  // g' = (1 - HU) S e^(S-1) / m^S, g'' = (1 - HU) S (S - 1) e^(S-2) / m^S; the integral by the
  // midpoint rule on 1e-6 steps.
  const double hu = 0.3, S_ = 1.5, m = 0.85, h = 1e-3;
  double bound = 0.0;
  for (int k = 0; k < 850000; ++k) {
    const double e = (k + 0.5) * 1e-6;
    const int i = e < 0.05 ? 1 : e < 0.5 ? 2 : e < 0.8 ? 3 : 4;
    const double fp = (y_[i] - y_[i - 1]) / (x_[i] - x_[i - 1]);
    const double g1 = (1 - hu) * S_ * std::pow(e, S_ - 1) / std::pow(m, S_);
    const double g2 = (1 - hu) * S_ * (S_ - 1) * std::pow(e, S_ - 2) / std::pow(m, S_);
    bound += 1e-6 * std::abs(g2 * hand_f(e) + 2 * g1 * fp);
  }
  bound *= h * h / 12;
  // (g f)'' > 0 here, so the gap is the trapezoid's leading Euler-Maclaurin term itself: the
  // account misses nothing beyond the quadrature (the next term is O(h^4)).
  EXPECT_NEAR(gap / bound, 1.0, 1e-4) << "gap " << gap << ", bound " << bound;
  EXPECT_GT(pt.state[ldfoam_state::dissipation], 0.0);
}

TEST(LowDensityFoam, TensionIsLinearOrCutOff) {
  Point linear(foam());
  linear.stretch(1.1);
  EXPECT_NEAR(linear.P[0][0], 0.5, 1e-12);  // E_t (lambda - 1) = 5 x 0.1
  Point cut(foam(1.0, 1.0, 0.3));
  cut.stretch(1.1);
  EXPECT_NEAR(cut.P[0][0], 0.3, 1e-12);
  EXPECT_NEAR(cut.state[ldfoam_state::elastic_energy], 0.5 * 0.3 * 0.06 + 0.3 * 0.04, 1e-14);
}

TEST(LowDensityFoam, SuperposedRotationRotatesTheStressOnly) {
  const double c = std::cos(0.7), s = std::sin(0.7);
  const double Q[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  const double U[3][3] = {{0.45, 0.05, 0.0}, {0.05, 0.8, 0.02}, {0.0, 0.02, 1.05}};
  double QU[3][3];
  matrix3::multiply(Q, U, QU);
  Point a(foam(0.2, 2.0)), b(foam(0.2, 2.0));
  a.deform(U);
  b.deform(QU);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double qp = 0.0, qsq = 0.0;
      for (int k = 0; k < 3; ++k) {
        qp += Q[i][k] * a.P[k][j];
        for (int l = 0; l < 3; ++l) qsq += Q[i][k] * a.cauchy[k][l] * Q[j][l];
      }
      EXPECT_NEAR(b.P[i][j], qp, 1e-12);
      EXPECT_NEAR(b.cauchy[i][j], qsq, 1e-12);
    }
  for (int k = 0; k < S; ++k) EXPECT_NEAR(b.state[k], a.state[k], 1e-12) << k;
  // Uniaxial compression along a rotated material axis: the rotated uniaxial answer.
  const double e = 0.6;
  double F[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F[i][j] = (i == j ? 1.0 : 0.0) - e * Q[i][0] * Q[j][0];
  Point r(foam());
  r.deform(F);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(r.cauchy[i][j], -hand_f(e) * Q[i][0] * Q[j][0], 1e-12) << i << j;
}

TEST(LowDensityFoam, TangentBoundsEveryDirectionsSlope) {
  const auto p = foam(0.2, 2.0);
  // At F = I the bound law's tangent is K on the axial mode.
  const double H0[3][3] = {};
  double P[3][3], A[3][3][3][3], next[S], cauchy[3][3], state[S];
  ldfoam_initial_state(state);
  ASSERT_TRUE(ldfoam_stress_and_bound_tangent<3>(p, H0, state, P, A, next, cauchy));
  EXPECT_NEAR(A[0][0][0][0], 52.0, 1e-8);
  EXPECT_NEAR(A[0][1][0][1] + A[0][1][1][0], 52.0, 1e-8);  // shear of the symmetric part
  // The law's own slopes dT/dlambda by central differences on the loading and unloading
  // branches of a point crushed to 0.95 and unloaded: all below K.
  Point pt(p);
  for (int k = 1; k <= 95; ++k) pt.stretch(1.0 - k * 0.01);
  double largest = 0.0;
  for (int k = 949; k >= 1; --k) {
    const double e = k * 1e-3, h = 1e-7;
    double Pp[3][3], Pm[3][3], n[S], cs[3][3];
    const double Hp[3][3] = {{-e + h, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const double Hm[3][3] = {{-e - h, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    ASSERT_TRUE(ldfoam_update<3>(p, Hp, pt.state, Pp, n, cs));
    ASSERT_TRUE(ldfoam_update<3>(p, Hm, pt.state, Pm, n, cs));
    largest = std::fmax(largest, (Pp[0][0] - Pm[0][0]) / (2 * h));
  }
  EXPECT_LT(largest, p.stiffness);
  EXPECT_GT(largest, 20.0);  // the densification slope, at least
}

}  // namespace
}  // namespace efg::physics
