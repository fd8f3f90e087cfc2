#include "drivers/StableStepSchedule.hpp"

#include <algorithm>

namespace efg {

StableStepSchedule::StableStepSchedule(const ModelOperators& ops, const StageSpec& stage,
                                       bool active, const Vector& d)
    : ops_(ops),
      active_(active),
      update_strain_(stage.settings["dt_update_strain"].as<double>()),
      refresh_(stage.settings["dt_update_interval"].as<long long>()),
      d_estimated_(d, Teuchos::Copy),
      change_(d.getMap()),
      eroded_at_estimate_(ops.eroded_points()) {}

bool StableStepSchedule::due(long long steps, const Vector& d) {
  if (!active_ || steps < next_check_) return false;
  change_.update(1.0, d, -1.0, d_estimated_, 0.0);
  const double strain = ops_.largest_strain_change(change_);
  const long long since = steps - estimated_at_;
  eroded_ = ops_.eroded_points();
  if (strain >= update_strain_ || eroded_ != eroded_at_estimate_ || since >= refresh_) return true;
  // Half the remaining way at the strain's rate so far, and at most as far ahead as the last
  // estimate is behind (an impact's strain accelerates from nothing).
  const double remaining = strain > 0
                               ? 0.5 * static_cast<double>(since) * (update_strain_ / strain - 1.0)
                               : static_cast<double>(since);
  next_check_ =
      steps + std::clamp(std::min(static_cast<long long>(remaining), since), 1LL, refresh_ - since);
  return false;
}

void StableStepSchedule::estimated(long long steps, const Vector& d) {
  Tpetra::deep_copy(d_estimated_, d);
  estimated_at_ = steps;
  eroded_at_estimate_ = eroded_;
  next_check_ = steps + 1;
}

}  // namespace efg
