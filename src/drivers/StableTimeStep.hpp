// The critical time step of central differences, dt_crit = 2 / omega_max, with omega_max^2 the
// largest eigenvalue of M^-1 K (K the tangent of the internal force at the current state). It is
// estimated by power iteration on the symmetric form M^-1/2 K M^-1/2 with matrix-free products
// K v = (f_int(d + e v) - f_int(d)) / e, so no stiffness matrix is built. The estimate is
// warm-started from the previous eigenvector when it is refreshed during a run.
#pragma once

#include "operators/ModelOperators.hpp"

namespace efg {

class StableTimeStep {
 public:
  StableTimeStep(const ModelOperators& ops, const Vector& mass_owned);

  /// dt_crit at displacement d, after `iterations` power iterations (the first call uses at
  /// least 30).
  double estimate(const Vector& d_owned, int iterations = 8);
  double largest_frequency() const { return omega_; }

 private:
  const ModelOperators& ops_;
  Vector inv_sqrt_mass_, v_, d_, f0_, f1_;
  bool started_ = false;
  double omega_ = 0;
};

}  // namespace efg
