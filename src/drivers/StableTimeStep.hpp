// The critical time step of central differences, dt_crit = 2 / omega_max, with omega_max^2 the
// largest eigenvalue of M^-1 K (K the tangent of the internal force at the current state).
//
// Three estimates of lambda_max (stage key stable_step, docs/explicit.md "Stable time step"):
// - bound: a guaranteed upper bound that needs no iteration, from the integration points
//   (operators/StiffnessBound.hpp: x^T K x <= sum c_I x_I^2, so lambda_max <= max c / m);
//   1.5-4 times lambda_max, a step 0.5-0.8 times the critical one. Solid parts without mixed
//   u-p cells or weak supports; elsewhere the sharpened estimate stands in.
// - sharpened (the default): the largest Ritz value theta of a few Lanczos steps (Anasazi's
//   block Krylov-Schur stopped after kLanczosSteps products, no convergence needed) times the
//   safety factor kLanczosSafety, capped by the bound: min(bound, 1.1 theta). theta <= lambda_max
//   always (a Rayleigh quotient); 24 steps from a start vector with every mode in it reach
//   0.95-1.0 lambda_max on the explicit scenes of tests/cli/check_stable_step_margin.py.
//   Re-estimates in between scale the last Lanczos estimate by the largest growth of the rows'
//   bounds since (a stiffness that grew nowhere by more than g moved lambda_max by at most g),
//   while that growth is at most 10 % (at most 8 in a row).
// - converged: Krylov-Schur run to convergence, bound theta + ||A y - theta y|| (Parlett, "The
//   Symmetric Eigenvalue Problem", Thm. 4.5.1: an eigenvalue lies within the residual norm of
//   the Ritz value), the reference the others are measured against; 10-20 times the products.
// Models of at most 64 dofs take the exact dense eigenvalue in every method (a Krylov space the
// size of the problem breaks down on the rigid-body modes of one or two cells).
//
// A = M^-1/2 K M^-1/2 is applied matrix-free, K x = (f_int(d + e x) - f_int(d)) / e with e scaled
// to the sizes of d and x (unit-free), so no stiffness matrix is built.
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

/// How lambda_max(M^-1 K) is estimated (see above).
enum class StableStepMethod { sharpened, bound, converged };
/// The stage key's value ("sharpened", "bound", "converged").
StableStepMethod stable_step_method(const std::string& name);

class StableTimeStep {
 public:
  /// `wall_penalty`: the largest share P + 2 D of walls and contacts in the stability condition
  /// (their spring and damper; 0 without any): the step falls by sqrt(1 - wall_penalty / 4);
  /// `extra(d)` linearizes a further stiffness at d once per estimate; the product it returns
  /// adds K_extra(d) x to y.
  using StiffnessProduct = std::function<void(const Vector& x, Vector& y)>;
  using ExtraStiffness = std::function<StiffnessProduct(const Vector& d)>;
  StableTimeStep(const ModelOperators& ops, const Vector& mass_owned, double wall_penalty = 0.0,
                 ExtraStiffness extra = {}, StableStepMethod method = StableStepMethod::sharpened);
  /// Any internal force f(d) (owned dofs; e.g. the shells'), its stiffness probed the same way.
  /// `elastic_probe(on)` switches path-dependent points to their elastic response around each
  /// estimate (the stable step of elastic unloading), if given.
  using InternalForce = std::function<void(const Vector& d, Vector& f)>;
  StableTimeStep(InternalForce internal_force, const Vector& mass_owned,
                 std::function<void(bool)> elastic_probe = {},
                 StableStepMethod method = StableStepMethod::sharpened);

  /// dt_crit at displacement d.
  double estimate(const Vector& d_owned);
  /// omega_max of the solid (without the walls), and its bound's parts, from the last estimate.
  double largest_frequency() const { return omega_; }
  double ritz_value() const { return ritz_; }
  double residual_norm() const { return residual_; }
  /// The guaranteed bound of the last estimate (0 where none exists).
  double guaranteed_bound() const { return guaranteed_; }
  /// What the last estimate's lambda_max came from: "dense", "bound", "lanczos", "tracked
  /// bound" (the bound times the last Lanczos estimate's ratio to it), "converged".
  const std::string& source() const { return source_; }
  /// How many estimates so far ran the Lanczos steps (the costly ones: kLanczosSteps products).
  long long lanczos_runs() const { return lanczos_runs_; }

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
  /// The largest Ritz value of kLanczosSteps Lanczos steps (no convergence asked), or empty
  /// with `failure` saying why.
  std::optional<double> lanczos_ritz(const Teuchos::RCP<Tpetra::Operator<>>& A,
                                     std::string& failure);
  /// max c / m of the row bounds at d (empty where no bound exists).
  std::optional<double> row_bound(const Vector& d);
  /// The largest ratio of a row's bound (rows_) to its value at the last Lanczos estimate
  /// (infinite where that was 0 and now is not).
  double row_growth() const;
  /// The converged estimate (Krylov-Schur, the dense fallback for small models), or throws.
  double converged_step(const Teuchos::RCP<Tpetra::Operator<>>& A, const Map& map);

  InternalForce internal_force_;
  std::function<void(bool)> elastic_probe_;  ///< plastic points probed elastically while on
  Vector inv_sqrt_mass_, start_;
  /// The rows' bounds c of the last bound pass, and of the last Lanczos estimate.
  Vector rows_, lanczos_rows_;
  double wall_penalty_;
  ExtraStiffness extra_;
  StableStepMethod method_;
  /// c_owned = the row bounds of K(d); false where none exists (ModelOperators).
  std::function<bool(const Vector& d, Vector& c)> row_bounds_;
  Vector mass_;
  double omega_ = 0, ritz_ = 0, residual_ = 0, guaranteed_ = 0;
  /// The last Lanczos estimate of lambda_max, and the re-estimates that followed the rows'
  /// bounds since (sharpened).
  double lanczos_estimate_ = 0;
  int tracked_ = 0;
  long long lanczos_runs_ = 0;
  std::string source_;
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
