#include "drivers/MassDamping.hpp"

#include "parallel/ReproducibleSum.hpp"

namespace efg {

MassDamping::MassDamping(double alpha, const Vector& mass)
    : alpha_(alpha), mass_(mass), average_(mass.getMap()), momentum_(mass.getMap()) {}

void MassDamping::add_to_acceleration(const Vector& v, Vector& a) const {
  if (active()) a.update(-alpha_, v, 1.0);
}

void MassDamping::end_step(double dt, Vector& v, Vector& a) const {
  if (!active()) return;
  v.scale(1.0 / (1.0 + 0.5 * alpha_ * dt));
  a.update(-alpha_, v, 1.0);
}

double MassDamping::work(double dt, const Vector& v_old, const Vector& v_new) const {
  if (!active()) return 0.0;
  average_.update(0.5, v_old, 0.5, v_new, 0.0);
  momentum_.elementWiseMultiply(1.0, mass_, average_, 0.0);
  return alpha_ * dt * reproducible_dot(momentum_, average_);
}

}  // namespace efg
