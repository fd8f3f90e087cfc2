// One explicit step as the benchmarks time it: the velocity-Verlet updates around one internal
// force evaluation (unit mass, no loads: a = -f).
#pragma once

#include "operators/ModelOperators.hpp"

inline void explicit_step(const efg::ModelOperators& ops, double dt, efg::Vector& d, efg::Vector& v,
                          efg::Vector& a, efg::Vector& f) {
  v.update(0.5 * dt, a, 1.0);
  d.update(dt, v, 1.0);
  ops.internal_force(d, f);
  a.update(-1.0, f, 0.0);
  v.update(0.5 * dt, a, 1.0);
}
