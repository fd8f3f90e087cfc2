// Counts over the contact candidates of every rank (PenaltyContact, SurfaceContact): how many
// are tested, and how many were in contact at the last evaluation. Collective.
#pragma once

#include <Teuchos_Comm.hpp>
#include <Teuchos_CommHelpers.hpp>

namespace efg::contact {

/// Sum over ranks of `count(pair)` over the pairs (each with a `candidates` list).
template <class Pairs, class Count>
long long sum_over_ranks(const Teuchos::Comm<int>& comm, const Pairs& pairs, Count count) {
  long long mine = 0, all = 0;
  for (const auto& pair : pairs) mine += count(pair);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  return all;
}

template <class Pairs>
long long candidates_over_ranks(const Teuchos::Comm<int>& comm, const Pairs& pairs) {
  return sum_over_ranks(
      comm, pairs, [](const auto& pair) { return static_cast<long long>(pair.candidates.size()); });
}

template <class Pairs>
long long active_over_ranks(const Teuchos::Comm<int>& comm, const Pairs& pairs) {
  return sum_over_ranks(comm, pairs, [](const auto& pair) {
    long long n = 0;
    for (const auto& c : pair.candidates) n += c.active ? 1 : 0;
    return n;
  });
}

}  // namespace efg::contact
