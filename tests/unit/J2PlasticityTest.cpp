// J2 elastoplasticity (physics/materials/J2Plasticity.hpp) at one material point, against closed
// forms worked by hand: the uniaxial cycle of linear hardening, the finite-strain uniaxial state
// of perfect plasticity, plastic incompressibility, yield consistency, objectivity, the
// small-strain limit, the hardening curve, Cowper-Symonds, plane stress; the AD tangent
// (src/operators/MaterialTangent.hpp) against central differences; log and exp of symmetric
// matrices against the spectral closed form, with their derivatives at repeated eigenvalues.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "materials/ElasticConstants.hpp"
#include "materials/J2Plasticity.hpp"
#include "operators/MaterialTangent.hpp"
#include "tensor/SymmetricFunctions.hpp"

namespace efg::physics {
namespace {

constexpr int S = j2_state::count;
const double youngs = 200.0, poisson = 0.3, yield = 0.25, hardening = 20.0;
const ElasticConstants lame = elastic_constants(youngs, poisson);

J2Parameters linear(bool small_strain, double modulus = hardening) {
  J2Parameters p = j2_linear_hardening(lame.lambda, lame.mu, yield, modulus);
  p.small_strain = small_strain;
  return p;
}

template <int Dim>
struct Step {
  bool ok;
  double P[Dim][Dim], A[Dim][Dim][Dim][Dim], state[S], cauchy[3][3];
};

template <int Dim>
Step<Dim> step(const J2Parameters& p, const double (&H)[Dim][Dim], const double (&state)[S],
               double dt = 1.0) {
  Step<Dim> r;
  r.ok = j2_stress_and_tangent<Dim>(p, H, state, dt, r.P, r.A, r.state, r.cauchy);
  return r;
}

/// Rotation by angle about the unit axis (Rodrigues).
void rotation(const double (&axis)[3], double angle, double (&Q)[3][3]) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double w[3][3] = {{0, -axis[2], axis[1]}, {axis[2], 0, -axis[0]}, {-axis[1], axis[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      Q[i][j] = (i == j ? c : 0.0) + s * w[i][j] + (1 - c) * axis[i] * axis[j];
}

/// Q diag(d) Q^T.
void spectral(const double (&Q)[3][3], const double (&d)[3], double (&A)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      A[i][j] = 0;
      for (int k = 0; k < 3; ++k) A[i][j] += Q[i][k] * d[k] * Q[j][k];
    }
}

double max_abs(const double (&a)[3][3]) {
  double m = 0;
  for (auto& row : a)
    for (double x : row) m = std::max(m, std::abs(x));
  return m;
}

double max_diff(const double (&a)[3][3], const double (&b)[3][3]) {
  double m = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m = std::max(m, std::abs(a[i][j] - b[i][j]));
  return m;
}

/// ||dev tau|| for tau = J sigma.
double deviator_norm(const double (&sigma)[3][3], double J) {
  const double mean = (sigma[0][0] + sigma[1][1] + sigma[2][2]) / 3;
  double n = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = J * (sigma[i][j] - (i == j ? mean : 0.0));
      n += d * d;
    }
  return std::sqrt(n);
}

template <int Dim>
double det_of_identity_plus(const double (&H)[Dim][Dim]) {
  double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) F[i][j] += H[i][j];
  return matrix3::determinant(F);
}

TEST(SymmetricFunctions, LogAndExpMatchTheSpectralForm) {
  double Q[3][3];
  rotation({0.48, 0.6, 0.64}, 0.9, Q);
  // The rounding of A alone moves log A by ~ eps lambda_max / lambda_min: the tolerance is
  // 1e-14 up to a condition number of 20, then grows with it.
  const double cases[][3] = {
      {4.0, 0.3, 0.3},  {2.5, 1.2, 0.05},   {1.0, 1.0, 1.0}, {100.0, 1.0, 1.0},
      {1e-3, 1.0, 1.0}, {100.0, 0.2, 0.05}, {7.0, 7.0, 7.0}, {1.0 + 2e-6, 1.0 - 1e-6, 1.0}};
  for (const auto& lambda : cases) {
    const double condition =
        *std::max_element(lambda, lambda + 3) / *std::min_element(lambda, lambda + 3);
    double A[3][3], expected[3][3], L[3][3], logs[3], E[3][3];
    for (int k = 0; k < 3; ++k) logs[k] = std::log(lambda[k]);
    spectral(Q, lambda, A);
    spectral(Q, logs, expected);
    symmetric_log(A, L);
    EXPECT_LE(max_diff(L, expected),
              std::max(1e-14, 5e-16 * condition) * std::max(max_abs(expected), 1.0))
        << lambda[0] << " " << lambda[1] << " " << lambda[2];
    symmetric_exp(expected, E);
    EXPECT_LE(max_diff(E, A), 1e-14 * max_abs(A)) << lambda[0];
  }
}

/// d f(A)[W] of a symmetric matrix function at A = Q diag(l) Q^T by forward AD, against the
/// Daleckii-Krein form Q (f[l_i, l_j] o (Q^T W Q)) Q^T with the divided differences `divided`.
template <class Function, class Divided>
void check_derivative(Function f, Divided divided, const double (&Q)[3][3], const double (&l)[3]) {
  using Dual = Sacado::Fad::SFad<double, 1>;
  const double W[3][3] = {{0.3, -0.7, 0.2}, {-0.7, 0.5, 0.9}, {0.2, 0.9, -0.4}};
  double A[3][3], Wq[3][3] = {}, expected[3][3] = {};
  spectral(Q, l, A);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) Wq[i][j] += Q[a][i] * W[a][b] * Q[b][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          expected[i][j] += Q[i][a] * divided(l[a], l[b]) * Wq[a][b] * Q[j][b];
  Dual x[3][3], y[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      x[i][j] = Dual(1, 0, A[i][j]);
      x[i][j].fastAccessDx(0) = W[i][j];
    }
  f(x, y);
  double d[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d[i][j] = y[i][j].dx(0);
  EXPECT_LE(max_diff(d, expected), 1e-13 * max_abs(expected)) << l[0] << " " << l[1];
}

TEST(SymmetricFunctions, DerivativesAtRepeatedEigenvalues) {
  double identity[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Q[3][3];
  rotation({0.0, 0.6, 0.8}, 0.7, Q);
  using Dual = Sacado::Fad::SFad<double, 1>;
  auto log_of = [](const Dual(&a)[3][3], Dual(&b)[3][3]) { symmetric_log(a, b); };
  auto exp_of = [](const Dual(&a)[3][3], Dual(&b)[3][3]) { symmetric_exp(a, b); };
  // f[a, b] = (f(a) - f(b)) / (a - b), f'(a) at a = b; log1p / expm1 keep near-equal pairs exact.
  auto log_divided = [](double a, double b) {
    return a == b ? 1 / a : std::log1p((a - b) / b) / (a - b);
  };
  auto exp_divided = [](double a, double b) {
    return a == b ? std::exp(a) : std::exp(b) * std::expm1(a - b) / (a - b);
  };
  const double log_cases[][3] = {
      {1, 1, 1}, {3.0, 0.6, 0.6}, {0.5, 2.0, 2.0}, {2.0, 1.0, 1.0 + 1e-9}};
  const double exp_cases[][3] = {{0, 0, 0}, {1.1, -0.5, -0.5}, {-2.0, 0.7, 0.7}};
  for (const auto& l : log_cases) {
    check_derivative(log_of, log_divided, identity, l);
    check_derivative(log_of, log_divided, Q, l);
  }
  for (const auto& l : exp_cases) {
    check_derivative(exp_of, exp_divided, identity, l);
    check_derivative(exp_of, exp_divided, Q, l);
  }
}

/// One step of uniaxial stress along x in 3D: H = diag(e1, e2, e2) (small strain) or
/// diag(l1 - 1, l2 - 1, l2 - 1) (finite), e2 / l2 solved so that P22 = P33 = 0 (Newton with the
/// AD tangent). Updates `lateral` and `state`; returns the step.
Step<3> uniaxial_step(const J2Parameters& p, double axial, double& lateral, double (&state)[S]) {
  Step<3> r{};
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double H[3][3] = {{axial, 0, 0}, {0, lateral, 0}, {0, 0, lateral}};
    r = step<3>(p, H, state);
    if (!r.ok) break;
    if (std::abs(r.P[1][1]) < 1e-14) break;
    lateral -= r.P[1][1] / (r.A[1][1][1][1] + r.A[1][1][2][2]);
  }
  std::copy(r.state, r.state + S, state);
  return r;
}

TEST(J2Plasticity, SmallStrainUniaxialTensionCompressionCycle) {
  // Uniaxial stress, linear isotropic hardening (sigma_y + H alpha) by hand: yield at
  // e_y = sigma_y / E, then slope E_t = E H / (E + H) up to sigma_max at e_max; unloading is
  // elastic until -sigma_max (the hardened yield stress) at e_rev = e_max - 2 sigma_max / E, then
  // slope E_t again in compression.
  const J2Parameters p = linear(true);
  const double e_y = yield / youngs, e_t = youngs * hardening / (youngs + hardening);
  const double e_max = 0.01, sigma_max = yield + e_t * (e_max - e_y);
  const double e_rev = e_max - 2 * sigma_max / youngs;
  double state[S], lateral = 0;
  j2_initial_state(p, state);
  int plastic_tension = 0, elastic_unloading = 0, plastic_compression = 0;
  for (int k = 1; k <= 60; ++k) {
    const double e = k <= 20 ? k * 5e-4 : e_max - (k - 20) * 5e-4;  // up to 0.01, down to -0.01
    double expected;
    if (k <= 20) {
      expected = e <= e_y ? youngs * e : yield + e_t * (e - e_y);
      plastic_tension += e > e_y;
    } else if (e >= e_rev) {
      expected = sigma_max - youngs * (e_max - e);
      ++elastic_unloading;
    } else {
      expected = -sigma_max - e_t * (e_rev - e);
      ++plastic_compression;
    }
    const Step<3> r = uniaxial_step(p, e, lateral, state);
    ASSERT_TRUE(r.ok);
    EXPECT_NEAR(r.cauchy[0][0], expected, 1e-10) << "step " << k << " strain " << e;
    EXPECT_NEAR(r.cauchy[2][2], 0.0, 1e-12);
  }
  EXPECT_GT(plastic_tension, 10);
  EXPECT_GT(elastic_unloading, 5);
  EXPECT_GT(plastic_compression, 10);
}

TEST(J2Plasticity, FiniteStrainUniaxialPerfectPlasticity) {
  // With fixed principal axes the exponential return is exact in log strains: at yield the
  // elastic log strain is diag(1, -nu, -nu) sigma_y / E, so with axial log strain l1 the plastic
  // log strain is p diag(1, -1/2, -1/2), p = l1 - sigma_y / E, the lateral log strain
  // -nu sigma_y / E - p / 2, Cp^-1 = diag(e^-2p, e^p, e^p), Kirchhoff tau = diag(sigma_y, 0, 0)
  // and ||dev tau|| = sqrt(2/3) sigma_y.
  const J2Parameters p = linear(false, 0.0);
  double state[S], lateral = 0;
  j2_initial_state(p, state);
  for (int k = 1; k <= 10; ++k) {
    const double l1 = 0.05 * k, plastic = l1 - yield / youngs;
    const Step<3> r = uniaxial_step(p, std::expm1(l1), lateral, state);
    ASSERT_TRUE(r.ok);
    const double l2 = std::log1p(lateral), J = std::exp(l1 + 2 * l2);
    EXPECT_NEAR(l2, -poisson * yield / youngs - plastic / 2, 1e-13);
    EXPECT_NEAR(J * r.cauchy[0][0], yield, 1e-12);
    EXPECT_NEAR(deviator_norm(r.cauchy, J), std::sqrt(2.0 / 3.0) * yield, 1e-12);
    EXPECT_NEAR(state[j2_state::cp_inverse + 0], std::exp(-2 * plastic), 1e-12);
    EXPECT_NEAR(state[j2_state::cp_inverse + 1], std::exp(plastic), 1e-12);
    EXPECT_NEAR(state[j2_state::cp_inverse + 3], 0.0, 1e-14);
    EXPECT_NEAR(state[j2_state::alpha], plastic, 1e-12);
  }
}

/// The large 3D shear / stretch path of the finite-strain tests at load factor t.
void path(double t, double (&H)[3][3]) {
  const double G[3][3] = {{0.4, 0.8, 0.0}, {0.0, -0.1, 0.2}, {0.1, 0.0, 0.25}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) H[i][j] = t * G[i][j];
}

TEST(J2Plasticity, FiniteStrainIncompressibilityAndConsistency) {
  const J2Parameters p = linear(false);
  double state[S];
  j2_initial_state(p, state);
  int plastic = 0;
  for (int k = 1; k <= 10; ++k) {
    double H[3][3], cp[3][3];
    path(0.1 * k, H);
    const Step<3> r = step<3>(p, H, state);
    ASSERT_TRUE(r.ok);
    const bool yielded = r.state[j2_state::alpha] > state[j2_state::alpha];
    plastic += yielded;
    std::copy(r.state, r.state + S, state);
    j2_detail::unpack(state + j2_state::cp_inverse, cp);
    EXPECT_NEAR(matrix3::determinant(cp), 1.0, 1e-12) << "step " << k;
    // f = ||dev tau|| - sqrt(2/3) (sigma_y + H alpha): 0 after a plastic return, <= 0 otherwise.
    const double f = deviator_norm(r.cauchy, det_of_identity_plus<3>(H)) -
                     std::sqrt(2.0 / 3.0) * (yield + hardening * state[j2_state::alpha]);
    EXPECT_LE(f, 1e-10 * yield) << "step " << k;
    if (yielded) {
      EXPECT_GE(f, -1e-10 * yield) << "step " << k;
    }
  }
  EXPECT_GE(plastic, 8);
}

TEST(J2Plasticity, FiniteStrainIsObjective) {
  // F -> Q F: be_tr -> Q be_tr Q^T, so sigma -> Q sigma Q^T, P -> Q P and Cp^-1 is unchanged.
  const J2Parameters p = linear(false);
  double state[S], H[3][3], Q[3][3];
  j2_initial_state(p, state);
  for (int k = 1; k <= 9; ++k) {
    path(0.1 * k, H);
    const Step<3> r = step<3>(p, H, state);
    std::copy(r.state, r.state + S, state);
  }
  path(1.0, H);
  rotation({0.36, 0.48, 0.8}, 2.1, Q);
  double HQ[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      HQ[i][j] = Q[i][j] - (i == j ? 1.0 : 0.0);
      for (int k = 0; k < 3; ++k) HQ[i][j] += Q[i][k] * H[k][j];
    }
  const Step<3> a = step<3>(p, H, state), b = step<3>(p, HQ, state);
  ASSERT_TRUE(a.ok && b.ok);
  ASSERT_GT(a.state[j2_state::alpha], state[j2_state::alpha]);  // a plastic step
  double rotated[3][3] = {}, QP[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        QP[i][j] += Q[i][k] * a.P[k][j];
        for (int l = 0; l < 3; ++l) rotated[i][j] += Q[i][k] * a.cauchy[k][l] * Q[j][l];
      }
  EXPECT_LE(max_diff(b.cauchy, rotated), 1e-10 * max_abs(rotated));
  EXPECT_LE(max_diff(b.P, QP), 1e-10 * max_abs(QP));
  for (int k = 0; k < S; ++k) EXPECT_NEAR(b.state[k], a.state[k], 1e-12) << "state " << k;
}

TEST(J2Plasticity, FiniteStrainAtSmallStrainIsTheSmallStrainLaw) {
  // At strains of 1e-6 the two theories differ by O(1e-6) relative, elastic and plastic
  // (sigma_y = 1e-4: yield strain 5e-7), in 3D, plane strain and plane stress.
  const double G[3][3] = {{1.0, 0.5, 0.0}, {0.2, -0.4, 0.3}, {0.0, 0.1, 0.6}};
  for (double sigma_y : {1.0, 1e-4})
    for (int mode = 0; mode < 3; ++mode) {
      J2Parameters finite = j2_linear_hardening(lame.lambda, lame.mu, sigma_y, hardening), small;
      finite.plane_stress = mode == 2;
      small = finite;
      small.small_strain = true;
      double s_finite[S], s_small[S], sf[3][3], ss[3][3], alpha_small, alpha_finite;
      j2_initial_state(finite, s_finite);
      j2_initial_state(small, s_small);
      if (mode == 0) {
        double H[3][3];
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) H[i][j] = 1e-6 * G[i][j];
        const auto a = step<3>(finite, H, s_finite), b = step<3>(small, H, s_small);
        std::copy(&a.cauchy[0][0], &a.cauchy[0][0] + 9, &sf[0][0]);
        std::copy(&b.cauchy[0][0], &b.cauchy[0][0] + 9, &ss[0][0]);
        alpha_finite = a.state[j2_state::alpha], alpha_small = b.state[j2_state::alpha];
      } else {
        const double H[2][2] = {{1e-6 * G[0][0], 1e-6 * G[0][1]}, {1e-6 * G[1][0], 1e-6 * G[1][1]}};
        const auto a = step<2>(finite, H, s_finite), b = step<2>(small, H, s_small);
        std::copy(&a.cauchy[0][0], &a.cauchy[0][0] + 9, &sf[0][0]);
        std::copy(&b.cauchy[0][0], &b.cauchy[0][0] + 9, &ss[0][0]);
        alpha_finite = a.state[j2_state::alpha], alpha_small = b.state[j2_state::alpha];
      }
      if (sigma_y < 1) {
        EXPECT_GT(alpha_small, 1e-7) << "plastic, mode " << mode;
      }
      EXPECT_NEAR(alpha_finite, alpha_small, 1e-5 * alpha_small) << "mode " << mode;
      EXPECT_LE(max_diff(sf, ss), 1e-5 * max_abs(ss)) << "sigma_y " << sigma_y << " mode " << mode;
    }
}

/// A = dP/dH against central differences of P (h = 1e-6), relative to max |A|; `plastic`: the
/// step is expected to yield (so the check covers the intended branch).
template <int Dim>
void check_tangent(const J2Parameters& p, const double (&H)[Dim][Dim], const double (&state)[S],
                   double dt, bool plastic, const char* what) {
  const Step<Dim> r = step<Dim>(p, H, state, dt);
  ASSERT_TRUE(r.ok) << what;
  EXPECT_EQ(r.state[j2_state::alpha] > state[j2_state::alpha], plastic) << what;
  const double h = 1e-6;
  double worst = 0, scale = 0;
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) {
      double Hp[Dim][Dim], Hm[Dim][Dim], Pp[Dim][Dim], Pm[Dim][Dim], s[S], c[3][3];
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) Hp[i][j] = Hm[i][j] = H[i][j];
      Hp[k][l] += h;
      Hm[k][l] -= h;
      ASSERT_TRUE((j2_update<double, Dim>(p, Hp, state, dt, Pp, s, c)));
      ASSERT_TRUE((j2_update<double, Dim>(p, Hm, state, dt, Pm, s, c)));
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) {
          worst = std::max(worst, std::abs((Pp[i][j] - Pm[i][j]) / (2 * h) - r.A[i][j][k][l]));
          scale = std::max(scale, std::abs(r.A[i][j][k][l]));
        }
    }
  EXPECT_LT(worst, 1e-6 * scale) << what << (p.small_strain ? " small" : " finite")
                                 << (p.plane_stress ? " plane stress" : "") << " Dim " << Dim;
}

template <int Dim>
void check_tangents(J2Parameters p) {
  double fresh[S], loaded[S], c[3][3], P[Dim][Dim];
  j2_initial_state(p, fresh);
  double zero[Dim][Dim] = {}, H[Dim][Dim], uniaxial[Dim][Dim] = {}, more[Dim][Dim], less[Dim][Dim];
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) {
      H[i][j] = 0.02 * (i + 1) - 0.015 * j + (i == j ? 0.01 : 0.0);
      more[i][j] = 1.1 * H[i][j];
      less[i][j] = 0.995 * H[i][j];
    }
  uniaxial[0][0] = 0.05;  // be_tr = diag(a, b, b): repeated eigenvalues (not in plane stress)
  if (Dim == 3) uniaxial[1][1] = uniaxial[2][2] = -0.02;
  check_tangent<Dim>(p, zero, fresh, 1.0, false, "undeformed");
  check_tangent<Dim>(p, uniaxial, fresh, 1.0, true, "uniaxial plastic from undeformed");
  check_tangent<Dim>(p, H, fresh, 1.0, true, "plastic from undeformed");
  // From a plastic state (hardening curve, then Cowper-Symonds on): elastic unloading, further
  // rate-dependent plastic loading.
  p.curve_points = 2;
  p.curve_strain[0] = 0.01, p.curve_stress[0] = 0.35;
  p.curve_strain[1] = 0.05, p.curve_stress[1] = 0.45;
  ASSERT_TRUE((j2_update<double, Dim>(p, H, fresh, 1.0, P, loaded, c)));
  p.rate_c = 40.0, p.rate_p = 5.0;
  ASSERT_GT(loaded[j2_state::alpha], 0.0);
  check_tangent<Dim>(p, less, loaded, 1e-3, false, "elastic unloading from a plastic state");
  check_tangent<Dim>(p, more, loaded, 1e-3, true, "rate-dependent plastic from a plastic state");
}

TEST(J2Plasticity, TangentIsTheDerivativeOfTheStressUpdate) {
  for (bool small_strain : {false, true}) {
    J2Parameters p = linear(small_strain);
    check_tangents<3>(p);
    check_tangents<2>(p);
    p.plane_stress = true;
    check_tangents<2>(p);
  }
}

/// One small-strain step of simple shear H = gamma e1 (x) e2 from the undeformed state, with
/// gamma chosen by hand so that the return ends at alpha: ||s_tr|| = sqrt(2) mu gamma must equal
/// sqrt(2/3) sigma_y(alpha) + 2 mu sqrt(3/2) alpha. Returns sigma_12 (= sigma_y(alpha) / sqrt 3).
double shear_to(const J2Parameters& p, double alpha, double flow_stress, double dt,
                double& alpha_out) {
  const double q = std::sqrt(2.0 / 3.0) * flow_stress + 2 * p.mu * std::sqrt(1.5) * alpha;
  const double gamma = q / (std::sqrt(2.0) * p.mu);
  const double H[3][3] = {{0, gamma, 0}, {0, 0, 0}, {0, 0, 0}};
  double state[S];
  j2_initial_state(p, state);
  const Step<3> r = step<3>(p, H, state, dt);
  alpha_out = r.state[j2_state::alpha];
  return r.cauchy[0][1];
}

TEST(J2Plasticity, HardeningCurveIsInterpolatedLinearly) {
  // Points (0, 0.25) [initial], (0.01, 0.35), (0.05, 0.45), (0.2, 0.5); by hand:
  // sigma_y(0.005) = 0.30, sigma_y(0.03) = 0.40, and past the end sigma_y(0.3) = 0.5 + 0.1 / 3.
  J2Parameters p = linear(true);
  p.curve_points = 3;
  const double strains[] = {0.01, 0.05, 0.2}, stresses[] = {0.35, 0.45, 0.5};
  for (int i = 0; i < 3; ++i) p.curve_strain[i] = strains[i], p.curve_stress[i] = stresses[i];
  const double alphas[] = {0.005, 0.03, 0.3}, expected[] = {0.30, 0.40, 0.5 + 0.1 / 3};
  for (int i = 0; i < 3; ++i) {
    double alpha;
    const double s12 = shear_to(p, alphas[i], expected[i], 1.0, alpha);
    EXPECT_NEAR(alpha, alphas[i], 1e-13);
    EXPECT_NEAR(s12 * std::sqrt(3.0), expected[i], 1e-12) << alphas[i];
  }
}

TEST(J2Plasticity, CowperSymondsScalesTheYieldStress) {
  // alpha = 0.01 in dt = 1e-3: rate 10 / s; C = 40 / s, p = 5: factor 1 + (10 / 40)^(1/5).
  J2Parameters p = linear(true);
  p.rate_c = 40.0, p.rate_p = 5.0;
  const double flow = (yield + hardening * 0.01) * (1 + std::pow(0.25, 0.2));
  double alpha;
  const double s12 = shear_to(p, 0.01, flow, 1e-3, alpha);
  EXPECT_NEAR(alpha, 0.01, 1e-13);
  EXPECT_NEAR(s12 * std::sqrt(3.0), flow, 1e-12);
  p.rate_c = 0.0;  // off: the rate-independent yield stress
  const double s = shear_to(p, 0.01, yield + hardening * 0.01, 1e-3, alpha);
  EXPECT_NEAR(s * std::sqrt(3.0), yield + hardening * 0.01, 1e-12);
}

TEST(J2Plasticity, PlaneStressSolvesTheThicknessStrain) {
  // Small strain, elastic: sigma = E / (1 - nu^2) (eps_xx + nu eps_yy), eps_zz =
  // -nu / (1 - nu) (eps_xx + eps_yy).
  J2Parameters p = linear(true);
  p.yield_stress = 1e3, p.curve_stress[0] = 1e3;
  p.plane_stress = true;
  double state[S];
  j2_initial_state(p, state);
  const double H[2][2] = {{1e-3, 4e-4}, {0.0, -2e-4}};
  auto r = step<2>(p, H, state);
  const double c = youngs / (1 - poisson * poisson);
  EXPECT_NEAR(r.P[0][0], c * (1e-3 - poisson * 2e-4), 1e-12);
  EXPECT_NEAR(r.P[1][1], c * (-2e-4 + poisson * 1e-3), 1e-12);
  EXPECT_NEAR(r.P[0][1], youngs / (1 + poisson) * 2e-4, 1e-12);
  EXPECT_NEAR(r.state[j2_state::out_of_plane], -poisson / (1 - poisson) * 8e-4, 1e-15);
  // Finite strain, plastic: sigma_zz = 0 and the sheet thins.
  p = linear(false);
  p.plane_stress = true;
  j2_initial_state(p, state);
  const double big[2][2] = {{0.3, 0.1}, {0.05, 0.2}};
  r = step<2>(p, big, state);
  ASSERT_TRUE(r.ok);
  EXPECT_GT(r.state[j2_state::alpha], 0.1);
  EXPECT_NEAR(r.cauchy[2][2], 0.0, 1e-13 * max_abs(r.cauchy));
  EXPECT_LT(r.state[j2_state::out_of_plane], 0.9);
}

TEST(J2Plasticity, EnergyAccountOfSimpleShear) {
  // Small-strain simple shear gamma (eps_xy = gamma / 2), perfect plasticity, by hand: the shear
  // stress stays at k = sigma_y / sqrt(3) once gamma > k / mu, the plastic shear strain is
  // gamma - k / mu, so the plastic work is k (gamma - k / mu) and the stored energy k^2 / (2 mu).
  const double mu = 80.0, lambda = 120.0, sigma_y = 0.3, k = sigma_y / std::sqrt(3.0);
  J2Parameters p = j2_linear_hardening(lambda, mu, sigma_y, 0.0);
  p.small_strain = true;
  double state[j2_state::count], next[j2_state::count], cauchy[3][3];
  j2_initial_state(p, state);
  const double gamma_end = 5 * k / mu;
  for (int step = 1; step <= 10; ++step) {
    const double gamma = gamma_end * step / 10;
    const double H[3][3] = {{0, gamma, 0}, {0, 0, 0}, {0, 0, 0}};
    double P[3][3];
    ASSERT_TRUE((j2_update<double, 3>(p, H, state, 0.0, P, next, cauchy)));
    const double shear = std::min(mu * gamma, k);
    EXPECT_NEAR(P[0][1], shear, 1e-12 * k) << step;
    EXPECT_NEAR(next[j2_state::elastic_energy], shear * shear / (2 * mu), 1e-12 * k * k / mu);
    EXPECT_NEAR(next[j2_state::dissipation], k * std::max(0.0, gamma - k / mu),
                1e-12 * k * gamma_end);
    for (int c = 0; c < j2_state::count; ++c) state[c] = next[c];
  }
}

TEST(J2Plasticity, ErodedPointCarriesNoStressAndKeepsItsState) {
  // Simple shear, perfect plasticity: alpha = (2 / sqrt 3) (gamma / 2 - k / (2 mu)) by hand
  // (eps_p,xy = (gamma - k / mu) / 2, alpha = sqrt(2/3) |eps_p| = sqrt(2/3) sqrt(2) eps_p,xy).
  // The point fails in the step where alpha reaches failure_strain, still carrying its stress;
  // from the next step on P = 0 and the state is the one it failed with.
  const double mu = 80.0, lambda = 120.0, sigma_y = 0.3, k = sigma_y / std::sqrt(3.0);
  J2Parameters p = j2_linear_hardening(lambda, mu, sigma_y, 0.0);
  p.small_strain = true;
  const double gamma_fail = 3 * k / mu;
  p.failure_strain = (gamma_fail - k / mu) / std::sqrt(3.0);
  double state[j2_state::count], next[j2_state::count], cauchy[3][3], P[3][3];
  j2_initial_state(p, state);
  const double before[3][3] = {{0, 0.99 * gamma_fail, 0}, {0, 0, 0}, {0, 0, 0}};
  ASSERT_TRUE((j2_update<double, 3>(p, before, state, 0.0, P, next, cauchy)));
  EXPECT_EQ(next[j2_state::eroded], 0.0);
  const double at[3][3] = {{0, 1.01 * gamma_fail, 0}, {0, 0, 0}, {0, 0, 0}};
  ASSERT_TRUE((j2_update<double, 3>(p, at, next, 0.0, P, state, cauchy)));
  EXPECT_EQ(state[j2_state::eroded], 1.0);
  EXPECT_NEAR(P[0][1], k, 1e-12 * k);  // the failing step still carries its stress
  const double later[3][3] = {{0, 2 * gamma_fail, 0.1}, {0.05, 0, 0}, {0, 0, 0}};
  ASSERT_TRUE((j2_update<double, 3>(p, later, state, 0.0, P, next, cauchy)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(P[i][j], 0.0);
      EXPECT_EQ(cauchy[i][j], 0.0);
    }
  for (int c = 0; c < j2_state::count; ++c) EXPECT_EQ(next[c], state[c]) << c;
}

TEST(J2Plasticity, InvertedPointIsReported) {
  const J2Parameters p = linear(false);
  double state[S], P[2][2], next[S], c[3][3];
  j2_initial_state(p, state);
  const double H[2][2] = {{-1.5, 0}, {0, 0}};  // F_11 = -0.5
  EXPECT_FALSE((j2_update<double, 2>(p, H, state, 1.0, P, next, c)));
}

}  // namespace
}  // namespace efg::physics
