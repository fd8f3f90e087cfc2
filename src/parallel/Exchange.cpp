#include "parallel/Exchange.hpp"

#include <mpi.h>
#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace efg {
namespace {

std::vector<long long> offsets_of(const std::vector<long long>& counts) {
  std::vector<long long> offsets(counts.size() + 1, 0);
  std::partial_sum(counts.begin(), counts.end(), offsets.begin() + 1);
  return offsets;
}

}  // namespace

PackedLists exchange_packed(const CommPtr& comm, PackedLists outgoing) {
  const auto size = static_cast<std::size_t>(comm->getSize());
  if (outgoing.counts.size() != size)
    throw std::logic_error("exchange: one outgoing list per rank expected");
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(comm.get());
  if (!mpi || size == 1) return outgoing;  // one process: the list to itself
  const MPI_Comm raw = (*mpi->getRawMpiComm())();
  PackedLists received;
  received.counts.resize(size);
  MPI_Alltoall(outgoing.counts.data(), 1, MPI_LONG_LONG, received.counts.data(), 1, MPI_LONG_LONG,
               raw);
  const auto send_at = offsets_of(outgoing.counts), receive_at = offsets_of(received.counts);
  received.bytes.resize(static_cast<std::size_t>(receive_at.back()));
  long long largest[2] = {send_at.back(), receive_at.back()}, all[2] = {0, 0};
  MPI_Allreduce(largest, all, 2, MPI_LONG_LONG, MPI_MAX, raw);
  constexpr long long kIntMax = std::numeric_limits<int>::max();
  if (std::max(all[0], all[1]) <= kIntMax) {  // one call, in place
    std::vector<int> sc(size), sd(size), rc(size), rd(size);
    for (std::size_t q = 0; q < size; ++q) {
      sc[q] = static_cast<int>(outgoing.counts[q]);
      sd[q] = static_cast<int>(send_at[q]);
      rc[q] = static_cast<int>(received.counts[q]);
      rd[q] = static_cast<int>(receive_at[q]);
    }
    MPI_Alltoallv(outgoing.bytes.data(), sc.data(), sd.data(), MPI_CHAR, received.bytes.data(),
                  rc.data(), rd.data(), MPI_CHAR, raw);
    return received;
  }
  // Over 2 GiB on some rank: rounds of at most 2^30 / ranks bytes per list, whose counts and
  // displacements MPI's int can describe.
  const long long chunk = std::max(1LL, (1LL << 30) / static_cast<long long>(size));
  for (long long offset = 0;; offset += chunk) {
    std::vector<int> sc(size), sd(size), rc(size), rd(size);
    std::vector<char> send, receive;
    bool more = false;
    for (std::size_t q = 0; q < size; ++q) {
      const auto n = std::max(0LL, std::min(chunk, outgoing.counts[q] - offset));
      sd[q] = static_cast<int>(send.size());
      sc[q] = static_cast<int>(n);
      const auto from = outgoing.bytes.begin() + send_at[q] + offset;
      if (n > 0) send.insert(send.end(), from, from + n);
      more = more || outgoing.counts[q] > offset + chunk;
    }
    int total = 0;
    for (std::size_t s = 0; s < size; ++s) {
      const auto n = std::max(0LL, std::min(chunk, received.counts[s] - offset));
      rd[s] = total;
      rc[s] = static_cast<int>(n);
      total += rc[s];
      more = more || received.counts[s] > offset + chunk;
    }
    receive.resize(static_cast<std::size_t>(total));
    MPI_Alltoallv(send.data(), sc.data(), sd.data(), MPI_CHAR, receive.data(), rc.data(), rd.data(),
                  MPI_CHAR, raw);
    for (std::size_t s = 0; s < size; ++s)
      std::copy(receive.begin() + rd[s], receive.begin() + rd[s] + rc[s],
                received.bytes.begin() + receive_at[s] + offset);
    int any = more ? 1 : 0, all_any = 0;
    MPI_Allreduce(&any, &all_any, 1, MPI_INT, MPI_MAX, raw);
    if (!all_any) break;
  }
  return received;
}

}  // namespace efg
