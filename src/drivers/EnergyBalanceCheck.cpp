#include "drivers/EnergyBalanceCheck.hpp"

#include <sstream>

namespace efg {

bool EnergyBalanceCheck::failed(double balance_error) {
  if (!active()) return false;
  const bool over = balance_error > limit_;
  const bool both = over && over_before_;
  over_before_ = over;
  return both;
}

std::string EnergyBalanceCheck::message(double error, long long step, double time,
                                        const std::string& energies,
                                        const std::string& where) const {
  std::ostringstream o;
  o << "stage '" << stage_ << "': energy balance error " << 100 * error
    << " % exceeds energy_balance_limit (" << 100 * limit_ << " %) at step " << step
    << ", t = " << time << ": " << energies;
  if (!where.empty()) o << "; " << where;
  o << ". Energy without work is an instability the stable time step does not bound (a "
       "nonsymmetric operator: the traction term of transformation supports on irregular "
       "particles flutters, method nitsche does not), or a force whose work is not accounted; "
       "the last state is in the results. Raise energy_balance_limit (0: off) to run on";
  return o.str();
}

}  // namespace efg
