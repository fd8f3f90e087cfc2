// The explicit driver's stop on a failed energy balance. Central differences conserve
// E_kin + E_int - W_ext - W_wall to O(dt^2) when stable; energy that appears without work is an
// instability. A step above dt_crit shows as fast growth (the driver's 10x test), but an
// operator with complex eigenvalues (flutter: the nonsymmetric traction term of transformation
// supports on irregular particles) grows at any step size and slowly: a perturbed 10^3 block
// ended its stage at a 22 % balance error with 40 % of its energy from nowhere and no stop.
// Like LS-DYNA's ENDENG (*CONTROL_TERMINATION), the stage stops when the balance error exceeds
// `energy_balance_limit` (0: off), here at two checks in a row (every 100 steps and at every
// record), so that a one-check transient (an impact's first contact steps) does not stop it.
// Explicit shell stages check at their records.
#pragma once

#include <string>
#include <utility>

#include "drivers/RunState.hpp"

namespace efg {

class EnergyBalanceCheck {
 public:
  static constexpr long long interval = 100;  ///< steps between checks besides the records

  EnergyBalanceCheck(std::string stage, double limit) : stage_(std::move(stage)), limit_(limit) {}
  bool active() const { return limit_ > 0; }
  bool due(long long step) const { return active() && step % interval == 0; }
  /// Records this check's balance error; true when it and the previous check's exceed the limit.
  bool failed(double balance_error);
  bool failed(const RunState& state) { return failed(state.balance_error()); }
  /// The message: the error, `energies` (what was compared), the step, time, `where` (e.g. the
  /// particle with the largest kinetic energy; may be empty), what may cause it and how to go on.
  std::string message(double error, long long step, double time, const std::string& energies,
                      const std::string& where) const;

 private:
  std::string stage_;
  double limit_;
  bool over_before_ = false;
};

}  // namespace efg
