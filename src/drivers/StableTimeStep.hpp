// The critical time step of central differences, dt_crit = 2 / omega_max, with omega_max^2 the
// largest eigenvalue of M^-1 K (K the tangent of the internal force at the current state).
//
// The eigenvalue comes from Anasazi's block Krylov-Schur (a restarted Lanczos method) on the
// symmetric form A = M^-1/2 K M^-1/2, applied matrix-free, K x = (f_int(d + e x) - f_int(d)) / e
// with e scaled to the sizes of d and x (unit-free), so no stiffness matrix is built. The bound
// used is the Ritz value plus its residual norm, theta + ||A y - theta y|| (Parlett, "The
// Symmetric Eigenvalue Problem", Thm. 4.5.1: an eigenvalue lies within the residual norm of the
// Ritz value): above the largest eigenvalue once the Ritz value belongs to it, which the
// every-mode start vector ensures in practice. A power iteration with +5 % (the earlier estimate)
// fell 2 % short on the 1D wave bar.
//
// Rigid walls (penalty force k = p m / dt^2 on a particle behind the plane) add p / dt^2 to the
// particle's omega^2; central differences stay stable while dt^2 (omega_K^2 + p / dt^2) <= 4,
// i.e. dt <= 2 / omega_K sqrt(1 - p / 4): dt_crit is reduced by sqrt(1 - p_max / 4).
//
// Stiffness besides the solid's (the weak supports' boundary terms) enters through `extra`, as an
// exact product y += K_extra(d) x (symmetric; differences of nonlinear boundary terms are not
// exactly symmetric, and Anasazi's Hermitian Krylov-Schur then fails on complex Ritz values).
// A nonsymmetric term enters by its symmetric part, which bounds every real eigenvalue; complex
// ones (flutter, which no step size cures) are for the driver's energy balance to catch.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "operators/ModelOperators.hpp"

namespace efg {

class StableTimeStep {
 public:
  /// `wall_penalty`: the largest share P + 2 D of walls and contacts in the stability condition
  /// (their spring and damper; 0 without any): the step falls by sqrt(1 - wall_penalty / 4);
  /// `extra(d)` linearizes a further stiffness at d once per estimate; the product it returns
  /// adds K_extra(d) x to y.
  using StiffnessProduct = std::function<void(const Vector& x, Vector& y)>;
  using ExtraStiffness = std::function<StiffnessProduct(const Vector& d)>;
  StableTimeStep(const ModelOperators& ops, const Vector& mass_owned, double wall_penalty = 0.0,
                 ExtraStiffness extra = {});
  /// Any internal force f(d) (owned dofs; e.g. the shells'), its stiffness probed the same way.
  /// `elastic_probe(on)` switches path-dependent points to their elastic response around each
  /// estimate (the stable step of elastic unloading), if given.
  using InternalForce = std::function<void(const Vector& d, Vector& f)>;
  StableTimeStep(InternalForce internal_force, const Vector& mass_owned,
                 std::function<void(bool)> elastic_probe = {});

  /// dt_crit at displacement d.
  double estimate(const Vector& d_owned);
  /// omega_max of the solid (without the walls), and its bound's parts, from the last estimate.
  double largest_frequency() const { return omega_; }
  double ritz_value() const { return ritz_; }
  double residual_norm() const { return residual_; }

 private:
  /// dt_crit of a bound on the largest eigenvalue of M^-1 K (sets omega_; throws when it is 0
  /// or not finite).
  double step_of_bound(double bound);
  /// dt_crit of the exact largest eigenvalue (the dense path).
  double dense_step(double largest);
  /// The Krylov-Schur bound |theta| + ||A y - theta y|| on the largest eigenvalue of A, or empty
  /// with `failure` saying why (no convergence, an exception).
  std::optional<double> krylov_bound(const Teuchos::RCP<Tpetra::Operator<>>& A,
                                     std::string& failure);

  InternalForce internal_force_;
  std::function<void(bool)> elastic_probe_;  ///< plastic points probed elastically while on
  Vector inv_sqrt_mass_, start_;
  double wall_penalty_;
  ExtraStiffness extra_;
  double omega_ = 0, ritz_ = 0, residual_ = 0;
};

/// Throws NumericalError when a stage's given dt exceeds the stable step dt_crit at its start
/// (time `start`), unless allowed (allow_unstable_dt). Both steps in significant digits (a
/// fixed-point 0.000000 hid a stable step of 3.7e-8).
void refuse_unstable_dt(const std::string& stage, double dt, double dt_crit, double start,
                        bool allowed);

/// Throws InputError (naming the scene file) when a stage of length `span` needs more than 1e10
/// steps of dt; warns above 1e7.
void refuse_endless_stage(const std::string& file, const std::string& stage, double span, double dt,
                          double dt_crit);

}  // namespace efg
