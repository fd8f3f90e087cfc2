// J2 (von Mises) elastoplasticity with isotropic hardening, finite or small strain, at one
// integration point: the role of LS-DYNA *MAT_024 (piecewise linear plasticity).
//
// Finite strain (Simo, CMAME 99 (1992) 61-112; Eterovic & Bathe, IJNME 30 (1990) 1099-1114):
//   F = Fe Fp, state Cp^-1 = (Fp^T Fp)^-1 and the effective plastic strain alpha.
//   be_tr = F Cp^-1 F^T, eps_tr = 1/2 log be_tr, Kirchhoff tau = lambda tr(eps) I + 2 mu eps
//   (Hencky), the radial return below on dev tau, eps_e = eps_tr - dgamma n, be = exp(2 eps_e),
//   new Cp^-1 = F^-1 be F^-T, P = tau F^-T, Cauchy = tau / J. tr n = 0, so det Cp^-1 is kept
//   (plastic incompressibility), and F -> Q F rotates tau and leaves Cp^-1 alone (objectivity).
// Small strain (Simo & Hughes, "Computational Inelasticity", 1998, box 3.1): eps = sym(H),
//   eps_e_tr = eps - eps_p, the same return, eps_p += dgamma n, P = sigma.
// Radial return (box 3.1): q = ||dev tau_tr||; if q > sqrt(2/3) sigma_y(alpha_n), solve
//   g(dgamma) = q - 2 mu dgamma - sqrt(2/3) sigma_y(alpha_n + sqrt(2/3) dgamma) = 0 by a
//   safeguarded Newton to round-off; n = dev tau_tr / q, alpha += sqrt(2/3) dgamma. sigma_y is a
//   piecewise-linear curve in alpha times the Cowper-Symonds factor 1 + (alpha_dot / C)^(1/p),
//   alpha_dot = dalpha / dt (off when C = 0 or dt <= 0), solved implicitly with the rest.
// 2D: plane strain (F33 = 1, eps33 = 0) or plane stress: y = ln F33 (finite) or eps33 (small) is
//   solved so that tau33 = 0 (safeguarded Newton), with the exact slope dtau33/dy = C_3333 of
//   the consistent modulus of the return (Simo & Taylor, CMAME 48 (1985) 101-118) in log-strain
//   space (out-of-plane shears stay zero, so d eps_tr / dy = e3 (x) e3); the last y is kept in
//   the state as the next start.
// Scalar type T: double, or a forward-AD type with val() (Sacado SFad,
// src/operators/MaterialTangent.hpp) seeded on H for the tangent dP/dH. The local solves run on
// doubles; one closing Newton step in T carries the derivatives (implicit function theorem), so
// AD yields the exact consistent tangent without differentiating the iterations.
#pragma once

#include <math.h>  // sqrt, pow, log, exp, fabs: callable in host and device code

#include "tensor/Inline.hpp"
#include "tensor/SymmetricFunctions.hpp"
#include "tensor/Tensor.hpp"

namespace efg::physics {

struct J2Parameters {
  static constexpr int max_curve_points = 16;
  double lambda = 0.0;        ///< Lame's first parameter
  double mu = 0.0;            ///< shear modulus
  double yield_stress = 0.0;  ///< initial yield stress sigma_y(0)
  /// Hardening: yield stress curve_stress[i] at effective plastic strain curve_strain[i]
  /// (increasing, > 0), after the implicit first point (0, yield_stress); linear in between and
  /// beyond the last point with the last slope. No points: perfect plasticity. Linear hardening
  /// with modulus H: the one point (1, yield_stress + H). Softening needs slope > -3 mu.
  int curve_points = 0;
  double curve_strain[max_curve_points] = {};
  double curve_stress[max_curve_points] = {};
  double rate_c = 0.0;  ///< Cowper-Symonds C (1 / time); 0: rate independent
  double rate_p = 1.0;  ///< Cowper-Symonds p
  bool small_strain = false;
  bool plane_stress = false;  ///< 2D only: plane stress instead of plane strain
  /// Erosion: the point fails once its effective plastic strain reaches this value (0: never);
  /// from the next step on it carries no stress and its state stays as it was.
  double failure_strain = 0.0;
};

/// The law without yield (infinite yield stress, no hardening points): j2_update then returns
/// the elastic predictor from the committed state (the explicit stable-step probes).
EFG_PHYSICS_FUNCTION J2Parameters without_yield(J2Parameters p) {
  p.yield_stress = 1e300;
  p.curve_points = 0;
  return p;
}

/// The state of j2_update at one point: `count` doubles.
namespace j2_state {
constexpr int count = 11;
constexpr int cp_inverse = 0;      ///< finite strain: Cp^-1, stored xx yy zz xy yz zx
constexpr int plastic_strain = 0;  ///< small strain: eps_p, stored xx yy zz xy yz zx
constexpr int alpha = 6;           ///< effective plastic strain
constexpr int out_of_plane = 7;    ///< F33 (finite) or eps33 (small); plane stress solves it
constexpr int dissipation = 8;     ///< plastic work per unit reference volume, sum of tau : d eps_p
constexpr int elastic_energy = 9;  ///< stored energy 1/2 tau : eps_e per unit reference volume
constexpr int eroded = 10;         ///< 1 once the point has failed (erosion), else 0
}  // namespace j2_state

EFG_PHYSICS_FUNCTION J2Parameters j2_linear_hardening(double lambda, double mu, double yield_stress,
                                                      double modulus) {
  J2Parameters p;
  p.lambda = lambda, p.mu = mu, p.yield_stress = yield_stress;
  p.curve_points = 1, p.curve_strain[0] = 1.0, p.curve_stress[0] = yield_stress + modulus;
  return p;
}

/// The state before any deformation: Cp^-1 = I and F33 = 1 (finite), eps_p = 0 (small).
EFG_PHYSICS_FUNCTION void j2_initial_state(const J2Parameters& p,
                                           double (&state)[j2_state::count]) {
  for (int k = 0; k < j2_state::count; ++k) state[k] = 0.0;
  if (p.small_strain) return;
  for (int k = 0; k < 3; ++k) state[j2_state::cp_inverse + k] = 1.0;
  state[j2_state::out_of_plane] = 1.0;
}

/// sigma_y(alpha) of the hardening curve and its slope.
EFG_PHYSICS_FUNCTION double j2_curve_stress(const J2Parameters& p, double alpha, double& slope) {
  double x0 = 0.0, y0 = p.yield_stress;
  slope = 0.0;
  for (int i = 0; i < p.curve_points && i < J2Parameters::max_curve_points; ++i) {
    slope = (p.curve_stress[i] - y0) / (p.curve_strain[i] - x0);
    if (alpha <= p.curve_strain[i] || i + 1 == p.curve_points) break;
    x0 = p.curve_strain[i], y0 = p.curve_stress[i];
  }
  return y0 + slope * (alpha - x0);
}

/// Yield stress after a plastic increment dalpha >= 0 from alpha_n in time dt (curve x
/// Cowper-Symonds factor) and its derivative in dalpha.
EFG_PHYSICS_FUNCTION double j2_flow_stress(const J2Parameters& p, double alpha_n, double dalpha,
                                           double dt, double& slope) {
  const double s = j2_curve_stress(p, alpha_n + dalpha, slope);
  if (!(p.rate_c > 0) || !(dt > 0) || !(dalpha > 0)) return s;
  const double r = pow(dalpha / (dt * p.rate_c), 1.0 / p.rate_p);
  slope = slope * (1.0 + r) + s * r / (p.rate_p * dalpha);
  return s * (1.0 + r);
}

namespace j2_detail {

constexpr double sqrt_two_thirds = 0.81649658092772603273;

EFG_PHYSICS_FUNCTION void unpack(const double* s, double (&a)[3][3]) {
  unpack_symmetric(s, a);
}
EFG_PHYSICS_FUNCTION void pack(const double (&a)[3][3], double* s) {
  pack_symmetric(a, s);
}

/// Root of h (increasing through it, h(lo) <= 0 <= h(hi)) by Newton steps, bisecting when a
/// step leaves the bracket; stops when a step or the bracket is below x_tol.
template <class Fn>
EFG_PHYSICS_FUNCTION double bracketed_newton(const Fn& h, double x, double lo, double hi,
                                             double x_tol) {
  for (int iteration = 0; iteration < 200; ++iteration) {
    double slope;
    const double v = h(x, slope);
    if (v == 0) return x;
    (v < 0 ? lo : hi) = x;
    double next = x - v / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // also NaN or a zero slope
    if (fabs(next - x) <= x_tol || hi - lo <= x_tol) return next;
    x = next;
  }
  return x;
}

/// The return map of a trial elastic (log) strain eps: tau (T), the plastic strain increment
/// dgamma n and the new alpha (double), and column = d tau / d eps_33 of the consistent modulus
/// C = kappa 1 (x) 1 + 2 mu theta I_dev - 2 mu theta_bar n (x) n (Simo & Taylor 1985).
template <class T>
EFG_PHYSICS_FUNCTION void radial_return(const J2Parameters& p, const T (&eps)[3][3], double alpha_n,
                                        double dt, T (&tau)[3][3], double (&flow)[3][3],
                                        double& alpha, double (&column)[3][3]) {
  const double kappa = p.lambda + 2.0 * p.mu / 3.0, two_mu = 2.0 * p.mu;
  const T volumetric = eps[0][0] + eps[1][1] + eps[2][2];
  double n[3][3], q = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      tau[i][j] = two_mu * eps[i][j];
      if (i == j) tau[i][j] -= (two_mu / 3.0) * volumetric;
      n[i][j] = value_of(tau[i][j]);
      q += n[i][j] * n[i][j];
    }
  q = sqrt(q);
  const double k = sqrt_two_thirds;
  double slope, dgamma = 0.0, theta = 1.0, theta_bar = 0.0;
  const double trial_f = q - k * j2_flow_stress(p, alpha_n, 0.0, dt, slope);
  alpha = alpha_n;
  if (trial_f > 0) {
    auto minus_g = [&](double x, double& d) {  // -g(x) and -g'(x) > 0
      const double y = j2_flow_stress(p, alpha_n, k * x, dt, d);
      d = two_mu + k * k * d;
      return -(q - two_mu * x - k * y);
    };
    const double start = trial_f / (two_mu + k * k * (slope > 0 ? slope : 0.0));
    dgamma = bracketed_newton(minus_g, start, 0.0, q / two_mu, 1e-15 * q / two_mu);
    double d;
    const double r = -minus_g(dgamma, d);
    // The closing Newton step in T: dgamma_T = dgamma + g_T(dgamma) / (-g'), with only q_T
    // carrying derivatives (q_T has the value q).
    T q_t = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) q_t += tau[i][j] * tau[i][j];
    q_t = sqrt(q_t);
    const T dgamma_t = dgamma + (q_t - q + r) / d;
    const T factor = 1.0 - two_mu * dgamma_t / q_t;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) tau[i][j] *= factor;
    theta = 1.0 - two_mu * dgamma / q;
    theta_bar = two_mu / d - (1.0 - theta);
    alpha = alpha_n + k * dgamma;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = q > 0 ? n[i][j] / q : 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      flow[i][j] = dgamma * n[i][j];
      if (i == j) tau[i][j] += kappa * volumetric;
      column[i][j] = (i == j ? kappa - two_mu * theta / 3.0 : 0.0) +
                     (i == 2 && j == 2 ? two_mu * theta : 0.0) -
                     two_mu * theta_bar * n[i][j] * n[2][2];
    }
}

/// F (3 x 3, F33 = exp y in 2D) and the trial elastic strain: 1/2 log(F Cp^-1 F^T) (finite) or
/// sym(H) - eps_p with eps33 = y in 2D (small).
template <class T, int Dim>
EFG_PHYSICS_FUNCTION void trial_strain(const J2Parameters& p, const T (&H)[Dim][Dim], double y,
                                       const double (&history)[3][3], T (&F)[3][3],
                                       T (&eps)[3][3]) {
  deformation_gradient_3x3<T, Dim>(H, F);
  if (Dim == 2) F[2][2] = p.small_strain ? 1.0 + y : exp(y);
  if (p.small_strain) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        eps[i][j] = 0.5 * (F[i][j] + F[j][i]) - ((i == j ? 1.0 : 0.0) + history[i][j]);
    return;
  }
  T be[3][3];
  elastic_left_cauchy_green(F, history, be);
  symmetric_log(be, eps);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) eps[i][j] *= 0.5;
}

}  // namespace j2_detail

/// One step of the law: P (first Piola-Kirchhoff; small strain: Cauchy) from H = du/dX (total
/// Lagrangian), the state at the start of the step and the time step dt (rate term only). Writes
/// the state at the end of the step to new_state (old_state untouched) and the Cauchy stress.
/// Returns false (finite strain) when det F <= 0: P, new_state and cauchy are then undefined.
template <class T, int Dim>
EFG_PHYSICS_FUNCTION bool j2_update(const J2Parameters& p, const T (&H)[Dim][Dim],
                                    const double (&old_state)[j2_state::count], double dt,
                                    T (&P)[Dim][Dim], double (&new_state)[j2_state::count],
                                    double (&cauchy)[3][3]) {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");
  using namespace j2_detail;
  if (old_state[j2_state::eroded] > 0.5) {  // failed: no stress, the state kept as it was
    for (int k = 0; k < j2_state::count; ++k) new_state[k] = old_state[k];
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) P[i][j] = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) cauchy[i][j] = 0.0;
    return true;
  }
  double Hv[Dim][Dim], history[3][3], Fv[3][3], flow[3][3], column[3][3], alpha;
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) Hv[i][j] = value_of(H[i][j]);
  unpack(old_state + j2_state::cp_inverse, history);
  const double alpha_n = old_state[j2_state::alpha];
  const bool thin = Dim == 2 && p.plane_stress;
  const double f33_old = old_state[j2_state::out_of_plane];
  double y = !thin ? 0.0 : p.small_strain ? f33_old : log(f33_old > 0 ? f33_old : 1.0);
  if (!p.small_strain) {
    double F2[Dim][Dim];
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) F2[i][j] = Hv[i][j] + (i == j ? 1.0 : 0.0);
    if (!(determinant<Dim>(F2) > 0)) return false;
  }
  if (thin) {  // tau33(y) = 0: increasing in y, slope C_3333 >= kappa (without softening)
    auto tau33 = [&](double yy, double& slope) {
      double e[3][3], t[3][3], a;
      trial_strain<double, Dim>(p, Hv, yy, history, Fv, e);
      radial_return(p, e, alpha_n, dt, t, flow, a, column);
      slope = column[2][2];
      return t[2][2];
    };
    double slope;
    const double v = tau33(y, slope);
    if (v != 0) {  // bracket: the root is within |v| / kappa of y; widen if softening says not
      double lo = y, hi = y, step = 1.01 * fabs(v) / (p.lambda + 2.0 * p.mu / 3.0), w_slope;
      for (int k = 0; k < 60; ++k, step *= 2) {
        const double x = v < 0 ? y + step : y - step, w = tau33(x, w_slope);
        (w < 0 ? lo : hi) = x;
        if ((w < 0) != (v < 0)) break;
      }
      y = bracketed_newton(tau33, y - v / slope, lo, hi, 1e-16 + 1e-15 * fabs(y));
    }
  }
  T F[3][3], eps[3][3], tau[3][3];
  trial_strain<T, Dim>(p, H, y, history, F, eps);
  radial_return(p, eps, alpha_n, dt, tau, flow, alpha, column);
  if (thin) {  // closing Newton step in T on tau33 = 0
    const T dy = -tau[2][2] / column[2][2];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) tau[i][j] += column[i][j] * dy;
  }
  for (int k = 0; k < j2_state::count; ++k) new_state[k] = old_state[k];
  new_state[j2_state::alpha] = alpha;
  // Energy account: the step's plastic work tau : (dgamma n) (backward Euler, the stress at the
  // end of the step) and the Hencky stored energy 1/2 tau : eps_e, so that their sum is the
  // internal energy the explicit driver balances against the external work.
  double work = 0.0, stored = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      work += flow[i][j] * value_of(tau[i][j]);
      stored += 0.5 * value_of(tau[i][j]) * (value_of(eps[i][j]) - flow[i][j]);
    }
  new_state[j2_state::dissipation] = old_state[j2_state::dissipation] + work;
  new_state[j2_state::elastic_energy] = stored;
  if (p.failure_strain > 0 && alpha >= p.failure_strain) new_state[j2_state::eroded] = 1.0;
  if (thin) new_state[j2_state::out_of_plane] = p.small_strain ? y : exp(y);
  if (p.small_strain) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i < Dim && j < Dim) P[i][j] = tau[i][j];
        cauchy[i][j] = value_of(tau[i][j]);
        history[i][j] += flow[i][j];
      }
    pack(history, new_state + j2_state::plastic_strain);
    return true;
  }
  // P = tau F^-T; Cauchy = tau / J; Cp^-1 = F^-1 exp(2 (eps_tr - dgamma n)) F^-T.
  T Finv[3][3];
  matrix3::inverse(F, Finv);
  double Fi[3][3], be[3][3], t[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Fv[i][j] = value_of(F[i][j]);
      Fi[i][j] = value_of(Finv[i][j]);
      t[i][j] = 2.0 * (value_of(eps[i][j]) - flow[i][j]);
    }
  const double J = matrix3::determinant(Fv);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      P[i][a] = tau[i][0] * Finv[a][0];
      for (int b = 1; b < 3; ++b) P[i][a] += tau[i][b] * Finv[a][b];
    }
  symmetric_exp(t, be);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      cauchy[i][j] = value_of(tau[i][j]) / J;
      t[i][j] = Fi[i][0] * be[0][j] + Fi[i][1] * be[1][j] + Fi[i][2] * be[2][j];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      history[i][j] = t[i][0] * Fi[j][0] + t[i][1] * Fi[j][1] + t[i][2] * Fi[j][2];
  pack(history, new_state + j2_state::cp_inverse);
  return true;
}

}  // namespace efg::physics
