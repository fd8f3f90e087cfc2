// What the benchmarks share: one explicit step as they time it (the velocity-Verlet updates
// around one internal force evaluation; unit mass, no loads: a = -f), their clock and their
// "--name value" options.
#pragma once

#include <chrono>
#include <cstdlib>
#include <cstring>

#include "operators/ModelOperators.hpp"

inline void explicit_step(const efg::ModelOperators& ops, double dt, efg::Vector& d, efg::Vector& v,
                          efg::Vector& a, efg::Vector& f) {
  v.update(0.5 * dt, a, 1.0);
  d.update(dt, v, 1.0);
  ops.internal_force(d, f);
  a.update(-1.0, f, 0.0);
  v.update(0.5 * dt, a, 1.0);
}

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The value after `name` on the command line, or `fallback`.
inline long long bench_option(int argc, char** argv, const char* name, long long fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], name) == 0) return std::atoll(argv[i + 1]);
  return fallback;
}
