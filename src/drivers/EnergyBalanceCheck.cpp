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

std::string EnergyBalanceCheck::message(const RunState& state, long long step, long long particle,
                                        const double* position, int dim) const {
  std::ostringstream o;
  o << "stage '" << stage_ << "': energy balance error " << 100 * state.balance_error()
    << " % exceeds energy_balance_limit (" << 100 * limit_ << " %) at step " << step
    << ", t = " << state.time << ": kinetic " << state.kinetic << " + internal " << state.internal
    << " against initial " << state.initial_energy << " + work of loads and "
    << "supports " << state.external_work << " + walls " << state.wall_work;
  if (particle >= 0) {
    o << "; the largest kinetic energy is at particle " << particle + 1 << " (X = (";
    for (int k = 0; k < dim; ++k) o << (k ? ", " : "") << position[k];
    o << "))";
  }
  o << ". Energy without work is an instability the stable time step does not bound (a "
       "nonsymmetric operator: the traction term of transformation supports on irregular "
       "particles flutters, method nitsche does not), or a force whose work is not accounted; "
       "the last state is in the results. Raise energy_balance_limit (0: off) to run on";
  return o.str();
}

}  // namespace efg
