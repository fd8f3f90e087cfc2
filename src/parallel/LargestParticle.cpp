#include "parallel/LargestParticle.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>

namespace efg {

ParticleValue largest_particle_sum(const Tpetra::Vector<>& w, int dim) {
  const auto& map = *w.getMap();
  const auto x = w.getLocalViewHost(Tpetra::Access::ReadOnly);
  // A particle's dofs are owned together and numbered consecutively.
  ParticleValue mine{-1, -std::numeric_limits<double>::infinity()};
  long long current = -1;
  double sum = 0;
  auto close = [&] {
    if (current >= 0 && sum > mine.value) mine = {current, sum};
  };
  for (std::size_t k = 0; k < x.extent(0); ++k) {
    const long long particle = map.getGlobalElement(static_cast<int>(k)) / dim;
    if (particle != current) {
      close();
      current = particle;
      sum = 0;
    }
    sum += x(k, 0);
  }
  close();
  const auto& comm = *map.getComm();
  ParticleValue all;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, mine.value, Teuchos::outArg(all.value));
  const long long candidate = mine.particle >= 0 && mine.value == all.value
                                  ? mine.particle
                                  : std::numeric_limits<long long>::max();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, candidate, Teuchos::outArg(all.particle));
  if (all.particle == std::numeric_limits<long long>::max()) all = {-1, 0};
  return all;
}

}  // namespace efg
