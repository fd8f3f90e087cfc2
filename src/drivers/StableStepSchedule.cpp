#include "drivers/StableStepSchedule.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include <algorithm>
#include <cmath>

namespace efg {
namespace {
// The change of the stable step aimed at between estimates, and the widest strain interval in
// multiples of dt_update_strain (a crushable part stiffens within strains of about 0.1).
constexpr double kTargetChange = 0.04;
constexpr double kWidest = 4.0;
}  // namespace

StableStepSchedule::StableStepSchedule(const ModelOperators& ops, const StageSpec& stage,
                                       bool active, const Vector& d, double dt_crit)
    : ops_(ops),
      active_(active),
      update_strain_(stage.settings["dt_update_strain"].as<double>()),
      refresh_(stage.settings["dt_update_interval"].as<long long>()),
      d_estimated_(d, Teuchos::Copy),
      change_(d.getMap()),
      eroded_at_estimate_(ops.eroded_points()) {
  last_dt_crit_ = dt_crit;
}

bool StableStepSchedule::due(long long steps, const Vector& d) {
  if (!active_ || steps < next_check_) return false;
  // The checks are part of what the stable step costs (bench/stable_step.sh's share).
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: stable time step"));
  const double interval = strain_interval();
  change_.update(1.0, d, -1.0, d_estimated_, 0.0);
  const double strain = ops_.largest_strain_change(change_, d);
  const long long since = steps - estimated_at_;
  eroded_ = ops_.eroded_points();
  if (strain >= interval || eroded_ != eroded_at_estimate_ || since >= refresh_) return true;
  // Half the remaining way at the strain's rate so far, and at most as far ahead as the last
  // estimate is behind (an impact's strain accelerates from nothing).
  const double remaining = strain > 0 ? 0.5 * static_cast<double>(since) * (interval / strain - 1.0)
                                      : static_cast<double>(since);
  next_check_ =
      steps + std::clamp(std::min(static_cast<long long>(remaining), since), 1LL, refresh_ - since);
  return false;
}

void StableStepSchedule::estimated(long long steps, const Vector& d, double dt_crit) {
  if (last_dt_crit_ > 0 && dt_crit > 0) {
    const double change = std::abs(std::log(dt_crit / last_dt_crit_));
    // Proportional to the change seen over this interval, doubling at most, never below 1.
    const double aimed = change > 0 ? widening_ * kTargetChange / change : kWidest;
    widening_ = std::clamp(aimed, 1.0, std::min(2.0 * widening_, kWidest));
  }
  last_dt_crit_ = dt_crit;
  Tpetra::deep_copy(d_estimated_, d);
  estimated_at_ = steps;
  eroded_at_estimate_ = eroded_;
  next_check_ = steps + 1;
}

}  // namespace efg
