// Crushable foam at one integration point, finite strain: the role of LS-DYNA *MAT_063
// (*MAT_CRUSHABLE_FOAM, MODEL 0): a yield stress that is a curve of the volumetric strain, a
// tension cut-off, elastic unloading, and plastic flow along the loaded principal direction only
// (plastic Poisson ratio 0: a block crushed between plates does not bulge). docs/foams.md
// derives the equations; the keyword's fields are in ../shared/reference/crash-materials.md 2.4
// (PyDyna `mat_crushable_foam.py`: "yield stress versus volumetric strain", TSC).
//
// Kinematics as J2Plasticity.hpp (Simo, CMAME 99 (1992) 61-112): F = Fe Fp, state Cp^-1,
//   be_tr = F Cp^-1 F^T, eps_tr = 1/2 log be_tr (Hencky), tau = lambda tr(eps_e) 1 + 2 mu eps_e.
// Yield (the box of *MAT_063, in principal Cauchy stresses sigma_a = tau_a / J):
//   -sigma_y(eps_v) <= sigma_a <= t_c,  eps_v = 1 - J  (J = det F, the relative volume V),
//   so in Kirchhoff stresses  lo = -J sigma_y(1 - J) <= tau_a <= hi = J t_c. J is fixed by F:
//   the box does not depend on the plastic state, and the return needs no iteration.
// Return (closest point in the energy norm, Simo & Hughes 1998 ch. 2.3 and sec. 5.2, the
//   multi-surface form): with tau_tr, eps_tr coaxial (isotropy), eps_e = eps_tr - sum_a p_a
//   n_a (x) n_a and the KKT conditions p_a <= 0 where tau_a = lo, p_a >= 0 where tau_a = hi,
//   p_a = 0 inside. The plastic strain of direction a is along n_a (x) n_a alone: the
//   associative flow of the box, whose normals are the principal projectors; its lateral
//   plastic strain is zero (plastic Poisson ratio 0). The QP min 1/2 (tau - tau_tr) C^-1
//   (tau - tau_tr) over the box is convex with C positive definite (nu in (-1, 1/2)): the 27
//   active sets are tried and the one satisfying KKT is the unique projection.
// Energy (per unit reference volume, as J2): stored psi = 1/2 tau : eps_e; dissipation
//   D += tau_{n+1} : dp (backward Euler). D + psi is the internal energy the explicit driver
//   balances against the external work.
// Principal directions come from a cyclic Jacobi decomposition in doubles: this law has no AD
//   path (its tangent, CrushableFoamTangent in src/operators/MaterialTangent.hpp, is the elastic
//   one, an upper bound of the stiffness for the explicit stable step; implicit stages refuse
//   the law at input).
#pragma once

#include <math.h>  // fabs, sqrt, log, exp

#include "tensor/Inline.hpp"
#include "tensor/SymmetricFunctions.hpp"
#include "tensor/Tensor.hpp"

namespace efg::physics {

struct CrushableFoamParameters {
  static constexpr int max_curve_points = 32;
  double lambda = 0.0;  ///< Lame's first parameter (elastic unloading)
  double mu = 0.0;      ///< shear modulus
  /// Yield stress curve_stress[i] (> 0) at volumetric strain curve_strain[i] = 1 - J (increasing,
  /// the first 0); linear in between, beyond the last point with the last slope when it rises
  /// (densification), constant otherwise; constant below 0 (dilatation).
  int curve_points = 0;
  double curve_strain[max_curve_points] = {};
  double curve_stress[max_curve_points] = {};
  double tension_cutoff = 0.0;  ///< largest principal Cauchy stress t_c >= 0
  bool elastic_only = false;    ///< no yield: the elastic predictor (stable-step probes)
};

/// The law without yield: the elastic predictor from the committed state.
EFG_PHYSICS_FUNCTION CrushableFoamParameters without_yield(CrushableFoamParameters p) {
  p.elastic_only = true;
  return p;
}

/// The state at one point: `count` doubles. Slots 6, 8, 9, 10 mean what they mean in j2_state
/// (the plastic-strain output column, dissipation, stored energy, erosion), so the solid kernels
/// read both laws' rows alike.
namespace foam_state {
constexpr int count = 11;
constexpr int cp_inverse = 0;      ///< Cp^-1, stored xx yy zz xy yz zx
constexpr int crush = 6;           ///< largest volumetric strain 1 - J reached
constexpr int unused = 7;          ///< 0
constexpr int dissipation = 8;     ///< plastic work per unit reference volume
constexpr int elastic_energy = 9;  ///< stored energy 1/2 tau : eps_e per unit reference volume
constexpr int eroded = 10;         ///< always 0 (no erosion)
}  // namespace foam_state

/// The state before any deformation: Cp^-1 = I.
EFG_PHYSICS_FUNCTION void foam_initial_state(double (&state)[foam_state::count]) {
  for (int k = 0; k < foam_state::count; ++k) state[k] = 0.0;
  for (int k = 0; k < 3; ++k) state[foam_state::cp_inverse + k] = 1.0;
}

/// sigma_y(eps_v) of the curve.
EFG_PHYSICS_FUNCTION double foam_yield_stress(const CrushableFoamParameters& p, double eps_v) {
  const int n = p.curve_points;
  if (n <= 0) return 0.0;
  if (n == 1 || eps_v <= p.curve_strain[0]) return p.curve_stress[0];
  for (int i = 1; i < n; ++i)
    if (eps_v <= p.curve_strain[i]) {
      const double t =
          (eps_v - p.curve_strain[i - 1]) / (p.curve_strain[i] - p.curve_strain[i - 1]);
      return p.curve_stress[i - 1] + t * (p.curve_stress[i] - p.curve_stress[i - 1]);
    }
  const double slope = (p.curve_stress[n - 1] - p.curve_stress[n - 2]) /
                       (p.curve_strain[n - 1] - p.curve_strain[n - 2]);
  return p.curve_stress[n - 1] + (slope > 0 ? slope * (eps_v - p.curve_strain[n - 1]) : 0.0);
}

namespace foam_detail {

EFG_PHYSICS_FUNCTION void unpack(const double* s, double (&a)[3][3]) {
  unpack_symmetric(s, a);
}
EFG_PHYSICS_FUNCTION void pack(const double (&a)[3][3], double* s) {
  pack_symmetric(a, s);
}

/// Eigenvalues w and eigenvectors (columns of v) of a symmetric 3 x 3 a: cyclic Jacobi rotations
/// (Golub & Van Loan, "Matrix Computations", 4th ed., alg. 8.5.3) until the off-diagonal part is
/// below 1e-30 of the norm; quadratic convergence, a handful of sweeps.
EFG_PHYSICS_FUNCTION void symmetric_eigen(const double (&a)[3][3], double (&w)[3],
                                          double (&v)[3][3]) {
  double m[3][3], norm = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      m[i][j] = a[i][j];
      v[i][j] = i == j ? 1.0 : 0.0;
      norm += a[i][j] * a[i][j];
    }
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = m[0][1] * m[0][1] + m[1][2] * m[1][2] + m[0][2] * m[0][2];
    if (!(off > 1e-30 * norm)) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (m[p][q] == 0.0) continue;
        const double theta = (m[q][q] - m[p][p]) / (2.0 * m[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
        const double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // m <- m J (columns p, q)
          const double mkp = m[k][p], mkq = m[k][q];
          m[k][p] = c * mkp - s * mkq;
          m[k][q] = s * mkp + c * mkq;
        }
        for (int k = 0; k < 3; ++k) {  // m <- J^T m (rows p, q)
          const double mpk = m[p][k], mqk = m[q][k];
          m[p][k] = c * mpk - s * mqk;
          m[q][k] = s * mpk + c * mqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  for (int i = 0; i < 3; ++i) w[i] = m[i][i];
}

/// The box return in principal space: the elastic principal strains e (trial), the bounds lo <=
/// tau_a <= hi; writes tau_a and the plastic strains p_a (KKT of the closest point, see the top).
EFG_PHYSICS_FUNCTION void box_return(double lambda, double mu, const double (&e)[3], double lo,
                                     double hi, double (&tau)[3], double (&p)[3]) {
  const double trace = e[0] + e[1] + e[2];
  double trial[3];
  for (int a = 0; a < 3; ++a) trial[a] = lambda * trace + 2.0 * mu * e[a];
  for (int a = 0; a < 3; ++a) tau[a] = trial[a], p[a] = 0.0;
  if (trial[0] >= lo && trial[0] <= hi && trial[1] >= lo && trial[1] <= hi && trial[2] >= lo &&
      trial[2] <= hi)
    return;
  // Active sets as base-3 digits: 0 free, 1 at lo, 2 at hi (digits of the components). C p_A
  // = tau_tr - bound on the active rows, with C_ab = lambda + 2 mu delta_ab restricted to A.
  double best = 1e300;
  for (int code = 1; code < 27; ++code) {
    int state[3] = {code % 3, (code / 3) % 3, code / 9};
    int active[3], n = 0;
    double bound[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
      if (state[a] != 0) active[n++] = a, bound[a] = state[a] == 1 ? lo : hi;
    // Solve (lambda 1 1^T + 2 mu I) x = r on the n active rows (Sherman-Morrison: x = (r -
    // lambda sum(r) / (2 mu + n lambda) 1) / (2 mu)).
    double r[3] = {0, 0, 0}, sum = 0.0, q[3] = {0, 0, 0};
    for (int k = 0; k < n; ++k) r[k] = trial[active[k]] - bound[active[k]], sum += r[k];
    const double shift = lambda * sum / (2.0 * mu + n * lambda);
    for (int k = 0; k < n; ++k) q[active[k]] = (r[k] - shift) / (2.0 * mu);
    bool ok = true;
    double t[3], ptrace = q[0] + q[1] + q[2];
    for (int a = 0; a < 3; ++a) {
      t[a] = trial[a] - lambda * ptrace - 2.0 * mu * q[a];
      if (state[a] == 0)
        ok = ok && t[a] >= lo - 1e-14 * (hi - lo) && t[a] <= hi + 1e-14 * (hi - lo);
      if (state[a] == 1) ok = ok && q[a] <= 0.0;
      if (state[a] == 2) ok = ok && q[a] >= 0.0;
    }
    if (!ok) continue;
    // KKT holds; among (degenerate) ties keep the smallest plastic strain.
    const double size = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    if (size < best) {
      best = size;
      for (int a = 0; a < 3; ++a) tau[a] = t[a], p[a] = q[a];
      for (int a = 0; a < 3; ++a)
        if (state[a] != 0) tau[a] = bound[a];  // exactly on the bound
    }
  }
}

}  // namespace foam_detail

/// One step of the law: P (first Piola-Kirchhoff) from H = du/dX (total Lagrangian; Dim 2 is
/// plane strain, F33 = 1) and the state at the start of the step; writes the state at the end
/// of the step and the Cauchy stress. Returns false when det F <= 0 (then nothing is defined).
template <int Dim>
EFG_PHYSICS_FUNCTION bool foam_update(const CrushableFoamParameters& p, const double (&H)[Dim][Dim],
                                      const double (&old_state)[foam_state::count],
                                      double (&P)[Dim][Dim], double (&new_state)[foam_state::count],
                                      double (&cauchy)[3][3]) {
  static_assert(Dim == 2 || Dim == 3, "2D or 3D");
  using namespace foam_detail;
  double F[3][3], history[3][3], be[3][3], eps[3][3];
  deformation_gradient_3x3<double, Dim>(H, F);
  const double J = matrix3::determinant(F);
  if (!(J > 0)) return false;
  unpack(old_state + foam_state::cp_inverse, history);
  elastic_left_cauchy_green(F, history, be);
  symmetric_log(be, eps);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) eps[i][j] *= 0.5;
  double e[3], n[3][3], tau_a[3], dp[3];
  symmetric_eigen(eps, e, n);
  // Cauchy bounds -sigma_y(1 - J) <= sigma_a <= t_c, i.e. J times them on tau.
  const double eps_v = 1.0 - J;
  const double lo = p.elastic_only ? -1e300 : -J * foam_yield_stress(p, eps_v);
  const double hi = p.elastic_only ? 1e300 : J * p.tension_cutoff;
  box_return(p.lambda, p.mu, e, lo, hi, tau_a, dp);
  double tau[3][3], work = 0.0, stored = 0.0;
  for (int a = 0; a < 3; ++a) {
    work += tau_a[a] * dp[a];
    stored += 0.5 * tau_a[a] * (e[a] - dp[a]);
  }
  // tau = sum_a tau_a n_a n_a^T; be_new = sum_a exp(2 (e_a - p_a)) n_a n_a^T.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      tau[i][j] = be[i][j] = 0.0;
      for (int a = 0; a < 3; ++a) {
        tau[i][j] += tau_a[a] * n[i][a] * n[j][a];
        be[i][j] += exp(2.0 * (e[a] - dp[a])) * n[i][a] * n[j][a];
      }
    }
  double Finv[3][3], t[3][3];
  matrix3::inverse(F, Finv);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      P[i][a] = 0.0;
      for (int b = 0; b < 3; ++b) P[i][a] += tau[i][b] * Finv[a][b];
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      cauchy[i][j] = tau[i][j] / J;
      t[i][j] = Finv[i][0] * be[0][j] + Finv[i][1] * be[1][j] + Finv[i][2] * be[2][j];
    }
  for (int i = 0; i < 3; ++i)  // Cp^-1 = F^-1 be F^-T
    for (int j = 0; j < 3; ++j)
      history[i][j] = t[i][0] * Finv[j][0] + t[i][1] * Finv[j][1] + t[i][2] * Finv[j][2];
  for (int k = 0; k < foam_state::count; ++k) new_state[k] = old_state[k];
  pack(history, new_state + foam_state::cp_inverse);
  if (eps_v > new_state[foam_state::crush]) new_state[foam_state::crush] = eps_v;
  new_state[foam_state::dissipation] = old_state[foam_state::dissipation] + work;
  new_state[foam_state::elastic_energy] = stored;
  return true;
}

/// P of the elastic predictor from the committed state, in any scalar type T (double, or a
/// forward-AD type: its derivative in H is the elastic tangent, CrushableFoamTangent). Returns
/// false when det F <= 0.
template <class T, int Dim>
EFG_PHYSICS_FUNCTION bool foam_elastic_predictor(const CrushableFoamParameters& p,
                                                 const T (&H)[Dim][Dim],
                                                 const double (&old_state)[foam_state::count],
                                                 T (&P)[Dim][Dim]) {
  T F[3][3], be[3][3], eps[3][3], tau[3][3], Finv[3][3];
  double history[3][3];
  foam_detail::unpack(old_state + foam_state::cp_inverse, history);
  deformation_gradient_3x3<T, Dim>(H, F);
  if (!(value_of(matrix3::determinant(F)) > 0)) return false;
  elastic_left_cauchy_green(F, history, be);
  symmetric_log(be, eps);
  const T trace = 0.5 * (eps[0][0] + eps[1][1] + eps[2][2]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) tau[i][j] = p.mu * eps[i][j] + (i == j ? p.lambda * trace : T(0.0));
  matrix3::inverse(F, Finv);
  for (int i = 0; i < Dim; ++i)
    for (int a = 0; a < Dim; ++a) {
      P[i][a] = tau[i][0] * Finv[a][0];
      for (int b = 1; b < 3; ++b) P[i][a] += tau[i][b] * Finv[a][b];
    }
  return true;
}

}  // namespace efg::physics
