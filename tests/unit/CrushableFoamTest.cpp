// The crushable foam (physics/materials/CrushableFoam.hpp, the role of LS-DYNA *MAT_063) at one
// material point, against closed forms worked by hand (docs/foams.md):
//   uniaxial strain F = diag(lambda, 1, 1): J = lambda, eps_v = 1 - lambda; once yielding the
//     axial Cauchy stress is -sigma_y(eps_v) (the box's lower face), the plastic strain is axial
//     only, so the lateral elastic strain stays 0 and tau_22 = lambda_L / (lambda_L + 2 mu)
//     tau_11 = nu / (1 - nu) tau_11;
//   unloading in uniaxial strain: d tau_11 = (lambda_L + 2 mu) d ln(lambda) (Hencky, the
//     constrained modulus M = E (1 - nu) / ((1 + nu)(1 - 2 nu))), d tau_22 = lambda_L d ln(lambda);
//   uniaxial stress: the lateral log strain is -nu times the elastic axial strain (tau_11 / E)
//     and nothing of the plastic one: with nu = 0 the block does not bulge;
//   tension: the axial Cauchy stress stops at the cut-off t_c;
//   energy: with nu = 0 the backward-Euler account telescopes to D + psi = sum tau_{n+1} d eps -
//     sum (d tau)^2 / (2 E) exactly, and approaches the closed-form work E ln(lambda_y)^2 / 2 +
//     int sigma_y(e) de within the quadrature bound 1/2 sum |d tau d eps|.
// The yield curve (MPa): (0, 0.6) (0.1, 0.8) (0.6, 1.0) (0.8, 3.0) (0.9, 10), beyond it the last
// slope 70: by hand sigma_y(0.05) = 0.7, (0.35) = 0.9, (0.7) = 2.0, (0.85) = 6.5, (0.95) = 13.5.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/CrushableFoam.hpp"
#include "materials/ElasticConstants.hpp"
#include "operators/MaterialTangent.hpp"

namespace efg::physics {
namespace {

constexpr int S = foam_state::count;
const double youngs = 50.0;

CrushableFoamParameters foam(double nu, double tension_cutoff = 0.1) {
  const auto c = elastic_constants(youngs, nu);
  CrushableFoamParameters p;
  p.lambda = c.lambda, p.mu = c.mu;
  const double strain[] = {0.0, 0.1, 0.6, 0.8, 0.9}, stress[] = {0.6, 0.8, 1.0, 3.0, 10.0};
  p.curve_points = 5;
  for (int i = 0; i < 5; ++i) p.curve_strain[i] = strain[i], p.curve_stress[i] = stress[i];
  p.tension_cutoff = tension_cutoff;
  return p;
}

// The curve by hand (linear pieces; the last slope (10 - 3) / 0.1 = 70 beyond 0.9).
double hand_yield(double e) {
  const double x[] = {0.0, 0.1, 0.6, 0.8, 0.9}, y[] = {0.6, 0.8, 1.0, 3.0, 10.0};
  if (e <= 0) return 0.6;
  for (int i = 1; i < 5; ++i)
    if (e <= x[i]) return y[i - 1] + (e - x[i - 1]) * (y[i] - y[i - 1]) / (x[i] - x[i - 1]);
  return 10.0 + 70.0 * (e - 0.9);
}

struct Point {
  CrushableFoamParameters p;
  double state[S];
  double P[3][3], cauchy[3][3];
  explicit Point(const CrushableFoamParameters& law) : p(law) { foam_initial_state(state); }
  /// One step to F = diag(f); commits the state.
  void stretch(double f1, double f2, double f3) {
    const double H[3][3] = {{f1 - 1, 0, 0}, {0, f2 - 1, 0}, {0, 0, f3 - 1}};
    double next[S];
    ASSERT_TRUE(foam_update<3>(p, H, state, P, next, cauchy));
    for (int k = 0; k < S; ++k) state[k] = next[k];
  }
};

TEST(CrushableFoam, HandValuesOfTheCurve) {
  const auto p = foam(0.0);
  const double e[] = {0.05, 0.35, 0.7, 0.85, 0.95, -0.2}, s[] = {0.7, 0.9, 2.0, 6.5, 13.5, 0.6};
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(foam_yield_stress(p, e[i]), s[i], 1e-14) << e[i];
}

TEST(CrushableFoam, UniaxialStrainFollowsTheYieldCurve) {
  const double nu = 0.25;
  Point pt(foam(nu));
  const double check[] = {0.05, 0.35, 0.7, 0.85, 0.95};
  int next = 0;
  for (int k = 1; k <= 1920; ++k) {  // eps_v = k / 2000 up to 0.96
    const double ev = k * 5e-4;
    pt.stretch(1.0 - ev, 1.0, 1.0);
    if (next < 5 && std::abs(ev - check[next]) < 1e-12) {
      const double sy = hand_yield(check[next]);
      EXPECT_NEAR(pt.cauchy[0][0], -sy, 1e-10 * sy) << "eps_v " << ev;
      // The plastic strain is axial only: the lateral stress keeps the elastic ratio.
      EXPECT_NEAR(pt.cauchy[1][1], nu / (1 - nu) * pt.cauchy[0][0], 1e-10 * sy) << ev;
      EXPECT_NEAR(pt.cauchy[2][2], pt.cauchy[1][1], 1e-12 * sy);
      EXPECT_NEAR(pt.state[foam_state::crush], ev, 1e-12);
      ++next;
    }
  }
  EXPECT_EQ(next, 5);
}

TEST(CrushableFoam, UniaxialStressDoesNotBulgeBeyondTheElasticPoissonStrain) {
  // nu = 0: F = diag(lambda, 1, 1) is the uniaxial stress state itself (no lateral stress).
  Point flat(foam(0.0));
  for (int k = 1; k <= 1800; ++k) {
    flat.stretch(1.0 - k * 5e-4, 1.0, 1.0);
    const double sy = hand_yield(k * 5e-4);
    if (k >= 100) {
      EXPECT_NEAR(flat.cauchy[0][0], -sy, 1e-10 * sy);
    }
    EXPECT_NEAR(flat.cauchy[1][1], 0.0, 1e-12 * sy);
    EXPECT_NEAR(flat.cauchy[2][2], 0.0, 1e-12 * sy);
  }
  // nu = 0.3: the lateral log strain e2 that frees the sides, by hand: elastic e2 = -nu ln l1;
  // plastic e2 = -nu tau_11 / E with tau_11 = -J sigma_y(1 - J), J = l1 exp(2 e2) (fixed point).
  const double nu = 0.3;
  Point side(foam(nu));
  bool plastic = false;
  for (int k = 1; k <= 1600; ++k) {
    const double l1 = 1.0 - k * 5e-4;
    double e2 = -nu * std::log(l1), J = l1 * std::exp(2 * e2);
    if (youngs * std::abs(std::log(l1)) > J * hand_yield(1 - J)) {
      plastic = true;
      for (int it = 0; it < 200; ++it) {
        J = l1 * std::exp(2 * e2);
        e2 = nu * J * hand_yield(1 - J) / youngs;
      }
      J = l1 * std::exp(2 * e2);
    }
    side.stretch(l1, std::exp(e2), std::exp(e2));
    const double sy = hand_yield(1 - J);
    EXPECT_NEAR(side.cauchy[1][1], 0.0, 1e-10 * sy) << k;
    if (plastic) {
      EXPECT_NEAR(side.cauchy[0][0], -sy, 1e-10 * sy) << k;
    }
  }
  EXPECT_TRUE(plastic);
}

TEST(CrushableFoam, UnloadsAndReloadsWithTheConstrainedModulus) {
  const double nu = 0.25;
  const auto c = elastic_constants(youngs, nu);
  const double M = youngs * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // = lambda + 2 mu = 60
  EXPECT_NEAR(M, c.lambda + 2 * c.mu, 1e-12);
  Point pt(foam(nu));
  for (int k = 1; k <= 1000; ++k) pt.stretch(1.0 - k * 5e-4, 1.0, 1.0);  // to eps_v = 0.5
  const double lmax = 0.5, t1 = pt.cauchy[0][0] * lmax, t2 = pt.cauchy[1][1] * lmax;
  EXPECT_NEAR(pt.cauchy[0][0], -hand_yield(0.5), 1e-10);
  for (double l : {0.5005, 0.501, 0.502, 0.5005, 0.5}) {  // unload, then reload to lmax
    pt.stretch(l, 1.0, 1.0);
    const double d = std::log(l / lmax);
    EXPECT_NEAR(pt.cauchy[0][0] * l, t1 + M * d, 1e-12) << l;
    EXPECT_NEAR(pt.cauchy[1][1] * l, t2 + c.lambda * d, 1e-12) << l;
    EXPECT_NEAR(pt.state[foam_state::crush], 0.5, 1e-14);
  }
  EXPECT_NEAR(pt.cauchy[0][0], -hand_yield(0.5), 1e-10);  // back on the curve, no more flow
}

TEST(CrushableFoam, TensionIsCutOff) {
  for (double nu : {0.0, 0.25}) {
    const double tc = 0.2;
    Point pt(foam(nu, tc));
    for (int k = 1; k <= 400; ++k) {
      const double l = 1.0 + k * 5e-4;  // to 20 % extension
      pt.stretch(l, 1.0, 1.0);
      const double M = youngs * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
      if (M * std::log(l) > l * tc) {
        EXPECT_NEAR(pt.cauchy[0][0], tc, 1e-12) << nu << " " << l;
      } else {
        EXPECT_NEAR(pt.cauchy[0][0] * l, M * std::log(l), 1e-12);
      }
    }
    EXPECT_LE(pt.cauchy[1][1], tc);
  }
}

TEST(CrushableFoam, EnergyAccountTelescopesAndApproachesTheClosedFormWork) {
  Point pt(foam(0.0));
  double tau_old = 0.0, eps_old = 0.0, work = 0.0, numerical = 0.0, bound = 0.0;
  std::vector<double> path;
  for (int k = 1; k <= 1800; ++k) path.push_back(1.0 - k * 5e-4);  // crush to eps_v = 0.9
  double lambda_y = 0.0;
  for (double l : path) {
    pt.stretch(l, 1.0, 1.0);
    const double tau = pt.cauchy[0][0] * l, eps = std::log(l);
    work += tau * (eps - eps_old);
    numerical += (tau - tau_old) * (tau - tau_old) / (2 * youngs);
    bound += 0.5 * std::abs((tau - tau_old) * (eps - eps_old));
    tau_old = tau, eps_old = eps;
  }
  const double D = pt.state[foam_state::dissipation], psi = pt.state[foam_state::elastic_energy];
  EXPECT_NEAR(psi, tau_old * tau_old / (2 * youngs), 1e-14);
  EXPECT_NEAR(D + psi, work - numerical, 1e-13 * work);
  // The closed form: elastic to lambda_y (E |ln lambda_y| = lambda_y sigma_y(1 - lambda_y),
  // by bisection), then the area under the curve (exact for linear pieces: trapezoids).
  double lo = 0.9, hi = 1.0;
  for (int it = 0; it < 200; ++it) {
    lambda_y = 0.5 * (lo + hi);
    (youngs * std::abs(std::log(lambda_y)) > lambda_y * hand_yield(1 - lambda_y) ? lo : hi) =
        lambda_y;
  }
  const double ey = 1 - lambda_y;
  double area = 0.0;
  const double x[] = {ey, 0.1, 0.6, 0.8, 0.9};
  for (int i = 1; i < 5; ++i)
    area += 0.5 * (hand_yield(x[i - 1]) + hand_yield(x[i])) * (x[i] - x[i - 1]);
  const double exact = 0.5 * youngs * std::log(lambda_y) * std::log(lambda_y) + area;
  EXPECT_GT(D, 0.0);
  EXPECT_LE(std::abs(D + psi - exact), bound) << "exact " << exact << " bound " << bound;
  EXPECT_LT(bound, 2e-3 * exact);
}

TEST(CrushableFoam, ElasticTangentIsTheDerivativeOfThePredictor) {
  // A committed state with plastic strain (crushed along x to 0.6, then a rotated shear): the
  // tangent of the elastic predictor from it against central differences.
  // (A cut-off of 1 MPa: the unloading below puts the sides in tension, lambda_L d ln(lambda).)
  Point pt(foam(0.2, 1.0));
  for (int k = 1; k <= 40; ++k) pt.stretch(1.0 - k * 0.01, 1.0, 1.0);
  const double H[3][3] = {{-0.35, 0.12, 0.03}, {0.05, 0.02, -0.04}, {-0.02, 0.07, 0.01}};
  double P[3][3], A[3][3][3][3], next[S], cauchy[3][3];
  ASSERT_TRUE(foam_stress_and_elastic_tangent<3>(pt.p, H, pt.state, P, A, next, cauchy));
  const double h = 1e-6;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      double Hp[3][3], Hm[3][3], Pp[3][3], Pm[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Hp[i][j] = Hm[i][j] = H[i][j];
      Hp[k][l] += h, Hm[k][l] -= h;
      ASSERT_TRUE((foam_elastic_predictor<double, 3>(pt.p, Hp, pt.state, Pp)));
      ASSERT_TRUE((foam_elastic_predictor<double, 3>(pt.p, Hm, pt.state, Pm)));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(A[i][j][k][l], (Pp[i][j] - Pm[i][j]) / (2 * h), 1e-6 * youngs);
    }
  // Inside the box (unloaded from the crush at 0.6 to 0.61, a little shear) the update is the
  // predictor.
  const double small[3][3] = {{-0.39, 0.001, 0}, {0, 0.0, 0}, {0, 0, 0}};
  double Pe[3][3];
  ASSERT_TRUE(foam_update<3>(pt.p, small, pt.state, P, next, cauchy));
  ASSERT_TRUE((foam_elastic_predictor<double, 3>(pt.p, small, pt.state, Pe)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(P[i][j], Pe[i][j], 1e-12);
  EXPECT_EQ(next[foam_state::dissipation], pt.state[foam_state::dissipation]);
}

TEST(CrushableFoam, RotationRotatesTheStressAndLeavesTheState) {
  Point a(foam(0.2)), b(foam(0.2));
  const double c = std::cos(0.7), s = std::sin(0.7);
  const double Q[3][3] = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
  double F[3][3] = {{0.7, 0.1, 0.0}, {0.05, 0.9, 0.02}, {0.0, 0.03, 0.8}}, QF[3][3], H1[3][3],
         H2[3][3], P1[3][3], P2[3][3], s1[S], s2[S], c1[3][3], c2[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      QF[i][j] = Q[i][0] * F[0][j] + Q[i][1] * F[1][j] + Q[i][2] * F[2][j];
      H1[i][j] = F[i][j] - (i == j), H2[i][j] = QF[i][j] - (i == j);
    }
  ASSERT_TRUE(foam_update<3>(a.p, H1, a.state, P1, s1, c1));
  ASSERT_TRUE(foam_update<3>(b.p, H2, b.state, P2, s2, c2));
  EXPECT_GT(s1[foam_state::dissipation], 0.0);  // the step yields
  for (int k = 0; k < S; ++k) EXPECT_NEAR(s1[k], s2[k], 1e-12) << k;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double r = 0;
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) r += Q[i][k] * c1[k][l] * Q[j][l];
      EXPECT_NEAR(c2[i][j], r, 1e-12);
    }
}

TEST(CrushableFoam, InvertedPointIsReported) {
  Point pt(foam(0.0));
  const double H[3][3] = {{-1.1, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double P[3][3], next[S], cauchy[3][3];
  EXPECT_FALSE(foam_update<3>(pt.p, H, pt.state, P, next, cauchy));
}

}  // namespace
}  // namespace efg::physics
