// Coulomb friction by an elastic-slip (regularized stick) return map, a plain function for the
// penalty contact (no Trilinos). The old tangential force is turned into the new tangent plane
// (its normal part removed), loaded by the tangential slip increment through the stick
// stiffness k, and capped at mu F_n:
//   F_t* = P_t F_t_old - k P_t s,   F_t = F_t* min(1, mu F_n / |F_t*|),
//   mu = mu_d + (mu_s - mu_d) exp(-decay |P_t s| / dt)   (LS-DYNA's decay law).
#pragma once

#include <cmath>

namespace efg::contact {

struct Friction {
  double mu_s = 0, mu_d = 0, decay = 0;
};

/// The return map's outcome: the friction coefficient used, the trial force's size |F_t*| and
/// whether the cap acted (slip), for the implicit tangent.
struct CoulombState {
  double mu = 0, trial = 0;
  bool slipping = false;
};

/// The return map on T numbers (double, or forward-AD numbers: the implicit contact between
/// deformable parts differentiates it): ft_new from ft_old (constant: the committed force), the
/// slip increment s over dt, the unit normal n, the stick stiffness k and the normal force fn
/// (>= 0). Returns mu; `slipping` and `trial` as in CoulombState. A zero slip or trial force
/// takes no square root (its derivative there is infinite).
template <class T>
T coulomb_return_of(const Friction& law, const double* ft_old, const T* s, const T* n, double k,
                    const T& fn, double dt, int dim, T* ft_new, bool& slipping, T& trial) {
  using std::exp;
  using std::sqrt;
  T s_n = 0.0, ft_n = 0.0;
  for (int i = 0; i < dim; ++i) {
    s_n += s[i] * n[i];
    ft_n += ft_old[i] * n[i];
  }
  T ft2 = 0.0, slip2 = 0.0;
  for (int i = 0; i < dim; ++i) {
    const T st = s[i] - s_n * n[i];
    slip2 += st * st;
    ft_new[i] = ft_old[i] - ft_n * n[i] - k * st;
    ft2 += ft_new[i] * ft_new[i];
  }
  // (exp(-decay |s_t| / dt) is 1 at no decay or no slip: the same number as evaluating it)
  const T decayed = law.decay > 0 && slip2 > 0 ? T(exp(-law.decay * sqrt(slip2) / dt)) : T(1.0);
  const T mu = law.mu_d + (law.mu_s - law.mu_d) * decayed;
  const T limit = mu * fn;
  trial = ft2 > 0 ? T(sqrt(ft2)) : T(0.0);
  slipping = trial > limit;
  if (slipping)
    for (int i = 0; i < dim; ++i) ft_new[i] *= limit / trial;
  return mu;
}

/// ft_new from ft_old, the slip increment s over dt, the unit normal n, the stick stiffness k
/// and the normal force fn (>= 0).
inline CoulombState coulomb_return(const Friction& law, const double* ft_old, const double* s,
                                   const double* n, double k, double fn, double dt, int dim,
                                   double* ft_new) {
  CoulombState state;
  state.mu =
      coulomb_return_of(law, ft_old, s, n, k, fn, dt, dim, ft_new, state.slipping, state.trial);
  return state;
}

}  // namespace efg::contact
