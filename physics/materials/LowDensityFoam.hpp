// Low-density foam at one integration point, finite strain: the role of LS-DYNA *MAT_057
// (*MAT_LOW_DENSITY_FOAM): a nominal stress-strain loading curve in each principal direction of
// the stretch, no coupling between the directions (zero Poisson ratio), hysteretic unloading
// (HU, SHAPE), linear tension with an optional cut-off. docs/foams.md derives the equations;
// the keyword's fields and the public description ("no coupling in transverse directions",
// HU, SHAPE, TC, the time-step stiffness from the curve's largest slope) are collected in
// ../shared/reference/crash-materials.md 2.3 (PyDyna `mat_low_density_foam.py`; Ansys LS-DYNA
// user guide 6.8.1; d3view notes on tension and KCON).
//
// Kinematics: C = F^T F = sum_a lambda_a^2 N_a (x) N_a (reference principal directions N_a),
//   U = sum_a lambda_a N_a (x) N_a, R = F U^-1. Nominal compressive strain e_a = 1 - lambda_a.
// Stress: the Biot stress T = sum_a T_a N_a (x) N_a, coaxial with U, is work-conjugate to U
//   (P : dF = T : dU = sum_a T_a d lambda_a when T and U are coaxial; Ogden, "Non-linear
//   elastic deformations" (1984) sec. 3.5), so P = R T = F S with S = sum_a (T_a / lambda_a)
//   N_a (x) N_a, and the principal Cauchy stresses are sigma_a = T_a / (lambda_b lambda_c).
// Per direction (f the loading curve of nominal stress over e, m_a the largest e_a reached):
//   e_a >= m_a (loading):       T_a = -f(e_a), m_a <- e_a
//   0 <= e_a < m_a (unloading): T_a = -g(e_a; m_a) f(e_a),  g = HU + (1 - HU) (e / m)^SHAPE
//   e_a < 0 (tension):          T_a = min(E_t (lambda_a - 1), t_c)   (reversible)
//   g = 1 - (1 - HU)(1 - (e/m)^SHAPE) is the brief's/LS-DYNA's hysteresis factor written in the
//   strain ratio (an unloading curve that meets the loading curve at m and is HU times it at 0).
// Energy per unit reference volume, exact for fixed principal directions (docs/foams.md):
//   F(e) = int_0^e f,  I(e) = int_0^e x^S f(x) dx (closed form on each linear piece),
//   stored psi_a = HU F(e_a) + (1 - HU) I(e_a) / m_a^S  (e_a >= 0), E_t t^2 / 2 in tension,
//   dissipated Phi(m) = (1 - HU) (F(m) - I(m) / m^S), increasing in m, so D += Phi(m_new) -
//   Phi(m_old) >= 0 and psi + D equals the work sum_a int T_a d lambda_a along any path.
// History: M = sum_a m_a N_a (x) N_a in the reference frame (6 doubles). When the principal
//   directions turn in the material, m_a is read as N_a . M N_a (an approximation: the law keeps
//   a largest strain per material direction only where the directions stay put, as in uniaxial
//   and confined crush; rotations of the whole body leave U, hence everything, unchanged).
// Stiffness bound: every direction's slope dT_a / d lambda_a is at most
//   K = max(E_t, f'_max (1 + (1 - HU) SHAPE)):  on loading f' <= f'_max; on unloading
//   d(g f)/de = g f' + (1 - HU) SHAPE (e/m)^S f(e) / e <= f'_max + (1 - HU) SHAPE f'_max, since
//   g <= 1, f(e) <= f'_max e (f(0) = 0, f' >= 0) and e <= m. The tangent the solid kernels get is
//   that of the bound law P = K (F - R) (T_a = K (lambda_a - 1)), by forward AD; its largest
//   eigenvalue is K, so the explicit stable step built on it is safe for the principal modes.
#pragma once

#include <math.h>  // fabs, sqrt, pow

#include "materials/CrushableFoam.hpp"  // foam_detail: symmetric_eigen, pack, unpack
#include "tensor/Inline.hpp"
#include "tensor/SymmetricFunctions.hpp"

namespace efg::physics {

struct LowDensityFoamParameters {
  static constexpr int max_curve_points = 32;
  double tension_modulus = 0.0;  ///< E_t: slope of the nominal stress in tension
  /// Loading curve: nominal compressive stress curve_stress[i] (from 0, not decreasing) at
  /// nominal strain curve_strain[i] = 1 - lambda (from 0, increasing, < 1); linear in between,
  /// beyond the last point with the last slope.
  int curve_points = 0;
  double curve_strain[max_curve_points] = {};
  double curve_stress[max_curve_points] = {};
  double hysteresis = 1.0;        ///< HU in (0, 1]: 1 unloads on the loading curve (elastic)
  double shape = 1.0;             ///< SHAPE > 0
  double tension_cutoff = 1e300;  ///< largest nominal tensile stress t_c (default: none)
  double stiffness = 0.0;         ///< K, the bound of every direction's slope (see the top)
  bool bound_only = false;        ///< the bound law P = K (F - R) (stable-step probes)
};

EFG_PHYSICS_FUNCTION LowDensityFoamParameters without_yield(LowDensityFoamParameters p) {
  p.bound_only = true;
  return p;
}

/// The state at one point: `count` doubles, the columns 6, 8, 9, 10 meaning what they mean in
/// j2_state and foam_state (output column, dissipation, stored energy, erosion).
namespace ldfoam_state {
constexpr int count = 11;
constexpr int largest_strain = 0;  ///< M = sum_a m_a N_a (x) N_a, stored xx yy zz xy yz zx
constexpr int crush = 6;           ///< the largest nominal compressive strain reached
constexpr int unused = 7;          ///< 0
constexpr int dissipation = 8;     ///< hysteresis energy per unit reference volume
constexpr int elastic_energy = 9;  ///< recoverable energy per unit reference volume
constexpr int eroded = 10;         ///< always 0
}  // namespace ldfoam_state

EFG_PHYSICS_FUNCTION void ldfoam_initial_state(double (&state)[ldfoam_state::count]) {
  for (int k = 0; k < ldfoam_state::count; ++k) state[k] = 0.0;
}

namespace ldfoam_detail {

/// The index i of the curve piece [strain[i-1], strain[i]] holding e (the last one beyond).
EFG_PHYSICS_FUNCTION int piece(const LowDensityFoamParameters& p, double e) {
  for (int i = 1; i < p.curve_points; ++i)
    if (e <= p.curve_strain[i]) return i;
  return p.curve_points - 1;
}

EFG_PHYSICS_FUNCTION double slope(const LowDensityFoamParameters& p, int i) {
  return (p.curve_stress[i] - p.curve_stress[i - 1]) / (p.curve_strain[i] - p.curve_strain[i - 1]);
}

/// int_x0^x1 x^s (a + b x) dx.
EFG_PHYSICS_FUNCTION double moment(double a, double b, double s, double x0, double x1) {
  return a * (pow(x1, s + 1) - pow(x0, s + 1)) / (s + 1) +
         b * (pow(x1, s + 2) - pow(x0, s + 2)) / (s + 2);
}

}  // namespace ldfoam_detail

/// f(e), the loading curve (e >= 0).
EFG_PHYSICS_FUNCTION double ldfoam_loading_stress(const LowDensityFoamParameters& p, double e) {
  const int i = ldfoam_detail::piece(p, e);
  return p.curve_stress[i - 1] + ldfoam_detail::slope(p, i) * (e - p.curve_strain[i - 1]);
}

/// int_0^e x^s f(x) dx for e >= 0 (s = 0: F(e)), exact on the linear pieces.
EFG_PHYSICS_FUNCTION double ldfoam_curve_moment(const LowDensityFoamParameters& p, double e,
                                                double s) {
  double sum = 0.0;
  for (int i = 1; i < p.curve_points; ++i) {
    const double x0 = p.curve_strain[i - 1];
    if (e <= x0) break;
    const double x1 = i == p.curve_points - 1 || e < p.curve_strain[i] ? e : p.curve_strain[i];
    const double b = ldfoam_detail::slope(p, i), a = p.curve_stress[i - 1] - b * x0;
    sum += ldfoam_detail::moment(a, b, s, x0, x1);
  }
  return sum;
}

/// Phi(m), the energy one load-unload cycle to m dissipates (see the top).
EFG_PHYSICS_FUNCTION double ldfoam_cycle_dissipation(const LowDensityFoamParameters& p, double m) {
  if (!(m > 0)) return 0.0;
  return (1.0 - p.hysteresis) *
         (ldfoam_curve_moment(p, m, 0.0) - ldfoam_curve_moment(p, m, p.shape) / pow(m, p.shape));
}

/// The largest slope of the curve (its last piece continues beyond the last point).
EFG_PHYSICS_FUNCTION double ldfoam_largest_slope(const LowDensityFoamParameters& p) {
  double s = 0.0;
  for (int i = 1; i < p.curve_points; ++i) s = fmax(s, ldfoam_detail::slope(p, i));
  return s;
}

/// K = max(E_t, f'_max (1 + (1 - HU) SHAPE)): the bound of every direction's slope.
EFG_PHYSICS_FUNCTION double ldfoam_stiffness_bound(const LowDensityFoamParameters& p) {
  return fmax(p.tension_modulus, ldfoam_largest_slope(p) * (1.0 + (1.0 - p.hysteresis) * p.shape));
}

/// One direction: the nominal stress T at stretch lambda with the largest compression m (already
/// updated, m >= 1 - lambda), and the stored energy psi of that direction.
EFG_PHYSICS_FUNCTION void ldfoam_direction(const LowDensityFoamParameters& p, double lambda,
                                           double m, double& T, double& psi) {
  const double e = 1.0 - lambda;
  if (e < 0) {  // tension: linear, capped (reversible) at t_c
    const double t = lambda - 1.0, Et = p.tension_modulus, t0 = p.tension_cutoff / Et;
    T = fmin(Et * t, p.tension_cutoff);
    psi = t <= t0 ? 0.5 * Et * t * t : 0.5 * p.tension_cutoff * t0 + p.tension_cutoff * (t - t0);
    return;
  }
  const double HU = p.hysteresis, S = p.shape;
  const double ratio = m > 0 ? fmin(e / m, 1.0) : 1.0;
  T = -(HU + (1.0 - HU) * pow(ratio, S)) * ldfoam_loading_stress(p, e);
  psi = HU * ldfoam_curve_moment(p, e, 0.0) +
        (m > 0 ? (1.0 - HU) * ldfoam_curve_moment(p, e, S) / pow(m, S) : 0.0);
}

/// P = K (F - R) of the bound law, R = F U^-1, U = (F^T F)^(1/2), in any scalar type T (double,
/// or a forward-AD type: its derivative is the tangent the kernels get). False when det F <= 0.
template <class T, int Dim>
EFG_PHYSICS_FUNCTION bool ldfoam_bound_stress(const LowDensityFoamParameters& p,
                                              const T (&H)[Dim][Dim], T (&P)[Dim][Dim]) {
  T F[3][3], U[3][3], Uinv[3][3];
  deformation_gradient_3x3<T, Dim>(H, F);
  if (!(value_of(matrix3::determinant(F)) > 0)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) U[i][j] = F[0][i] * F[0][j] + F[1][i] * F[1][j] + F[2][i] * F[2][j];
  matrix3::square_root(U);
  matrix3::inverse(U, Uinv);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      T r = F[i][0] * Uinv[0][a] + F[i][1] * Uinv[1][a] + F[i][2] * Uinv[2][a];
      P[i][a] = p.stiffness * (F[i][a] - r);
    }
  return true;
}

/// One step of the law: P from H = du/dX (total Lagrangian; Dim 2 is plane strain, F33 = 1) and
/// the state at the start of the step; writes the state at the end of the step and the Cauchy
/// stress. Returns false when det F <= 0.
template <int Dim>
EFG_PHYSICS_FUNCTION bool ldfoam_update(const LowDensityFoamParameters& p,
                                        const double (&H)[Dim][Dim],
                                        const double (&old_state)[ldfoam_state::count],
                                        double (&P)[Dim][Dim],
                                        double (&new_state)[ldfoam_state::count],
                                        double (&cauchy)[3][3]) {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");
  double F[3][3], C[3][3], M[3][3], c[3], N[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      F[i][j] = (i < Dim && j < Dim ? H[i][j] : 0.0) + (i == j ? 1.0 : 0.0);
  const double J = matrix3::determinant(F);
  if (!(J > 0)) return false;
  for (int k = 0; k < ldfoam_state::count; ++k) new_state[k] = old_state[k];
  double S[3][3];  // second Piola-Kirchhoff stress
  if (p.bound_only) {
    double Pb[3][3], h[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) h[i][j] = F[i][j] - (i == j ? 1.0 : 0.0);
    ldfoam_bound_stress<double, 3>(p, h, Pb);
    double Finv[3][3];
    matrix3::inverse(F, Finv);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        S[i][j] = Finv[i][0] * Pb[0][j] + Finv[i][1] * Pb[1][j] + Finv[i][2] * Pb[2][j];
  } else {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        C[i][j] = F[0][i] * F[0][j] + F[1][i] * F[1][j] + F[2][i] * F[2][j];
    // Principal directions of C; where eigenvalues repeat (C = I after a full unload, the two
    // lateral directions of a uniaxial state) any basis of the eigenspace is one, and the
    // history would be smeared over it: the tiny multiple of M picks M's own directions there.
    // lambda_a^2 is the Rayleigh quotient N_a . C N_a (error O(1e-16) off degeneracy).
    foam_detail::unpack(old_state + ldfoam_state::largest_strain, M);
    double Cm[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Cm[i][j] = C[i][j] + 1e-9 * M[i][j];
    foam_detail::symmetric_eigen(Cm, c, N);
    for (int a = 0; a < 3; ++a) {
      c[a] = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c[a] += N[i][a] * C[i][j] * N[j][a];
    }
    double T[3], lambda[3], m[3], stored = 0.0, dissipated = 0.0;
    for (int a = 0; a < 3; ++a) {
      lambda[a] = sqrt(c[a]);
      double m_old = 0.0;  // N_a . M N_a
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m_old += N[i][a] * M[i][j] * N[j][a];
      m_old = fmax(m_old, 0.0);
      m[a] = fmax(m_old, 1.0 - lambda[a]);
      double psi = 0.0;
      ldfoam_direction(p, lambda[a], m[a], T[a], psi);
      stored += psi;
      dissipated += ldfoam_cycle_dissipation(p, m[a]) - ldfoam_cycle_dissipation(p, m_old);
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        S[i][j] = M[i][j] = 0.0;
        for (int a = 0; a < 3; ++a) {
          S[i][j] += T[a] / lambda[a] * N[i][a] * N[j][a];
          M[i][j] += m[a] * N[i][a] * N[j][a];
        }
      }
    foam_detail::pack(M, new_state + ldfoam_state::largest_strain);
    new_state[ldfoam_state::crush] =
        fmax(old_state[ldfoam_state::crush], fmax(m[0], fmax(m[1], m[2])));
    new_state[ldfoam_state::dissipation] = old_state[ldfoam_state::dissipation] + dissipated;
    new_state[ldfoam_state::elastic_energy] = stored;
  }
  double FS[3][3];
  matrix3::multiply(F, S, FS);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) P[i][a] = FS[i][a];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      cauchy[i][j] = (FS[i][0] * F[j][0] + FS[i][1] * F[j][1] + FS[i][2] * F[j][2]) / J;
  return true;
}

}  // namespace efg::physics
