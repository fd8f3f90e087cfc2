#include "drivers/StableTimeStep.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <cmath>

#include "parallel/ReproducibleSum.hpp"

namespace efg {

StableTimeStep::StableTimeStep(const ModelOperators& ops, const Vector& mass_owned)
    : ops_(ops),
      inv_sqrt_mass_(mass_owned.getMap()),
      v_(mass_owned.getMap()),
      d_(mass_owned.getMap()),
      f0_(mass_owned.getMap()),
      f1_(mass_owned.getMap()) {
  auto s = inv_sqrt_mass_.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto m = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < s.extent(0); ++k) s(k, 0) = 1.0 / std::sqrt(m(k, 0));
  // A start vector with every mode in it, the same on any number of ranks (by global id).
  auto v = v_.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto& map = *mass_owned.getMap();
  for (std::size_t k = 0; k < v.extent(0); ++k)
    v(k, 0) = std::sin(1.0 + 0.7 * static_cast<double>(map.getGlobalElement(static_cast<int>(k))) *
                                 1.618);
}

double StableTimeStep::estimate(const Vector& d_owned, int iterations) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: stable time step"));
  if (!started_) iterations = std::max(iterations, 30);
  started_ = true;
  ops_.internal_force(d_owned, f0_);
  const double scale = std::max(1e-12, 1e-7 * std::max(1.0, d_owned.normInf()));
  double lambda = 0;
  for (int it = 0; it < iterations; ++it) {
    const double norm = reproducible_norm2(v_);
    v_.scale(1.0 / norm);
    // w = M^-1/2 K M^-1/2 v with K x = (f(d + e x) - f(d)) / e.
    Tpetra::deep_copy(d_, d_owned);
    Vector x(v_.getMap());
    x.elementWiseMultiply(1.0, inv_sqrt_mass_, v_, 0.0);
    d_.update(scale, x, 1.0);
    ops_.internal_force(d_, f1_);
    f1_.update(-1.0 / scale, f0_, 1.0 / scale);
    v_.elementWiseMultiply(1.0, inv_sqrt_mass_, f1_, 0.0);
    lambda = reproducible_norm2(
        v_);  // ||A v|| with ||v|| = 1 approaches the largest eigenvalue from below
  }
  // Power iteration underestimates lambda_max: add 5 % so that dt_crit errs on the safe side.
  omega_ = std::sqrt(1.05 * lambda);
  return 2.0 / omega_;
}

}  // namespace efg
