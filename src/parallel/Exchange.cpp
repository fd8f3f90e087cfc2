#include "parallel/Exchange.hpp"

#include <mpi.h>
#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <stdexcept>

namespace efg {

std::vector<std::vector<char>> exchange_bytes(const CommPtr& comm,
                                              const std::vector<std::vector<char>>& outgoing) {
  const auto size = static_cast<std::size_t>(comm->getSize());
  if (outgoing.size() != size)
    throw std::logic_error("exchange: one outgoing list per rank expected");
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(comm.get());
  if (!mpi || size == 1) return outgoing;  // one process: the list to itself
  const MPI_Comm raw = (*mpi->getRawMpiComm())();
  // Counts first (as long long: a list may pass 2 GiB), then the bytes in rounds whose counts
  // and displacements MPI's int can describe.
  std::vector<long long> send_count(size), receive_count(size);
  for (std::size_t q = 0; q < size; ++q) send_count[q] = static_cast<long long>(outgoing[q].size());
  MPI_Alltoall(send_count.data(), 1, MPI_LONG_LONG, receive_count.data(), 1, MPI_LONG_LONG, raw);
  std::vector<std::vector<char>> received(size);
  for (std::size_t s = 0; s < size; ++s)
    received[s].resize(static_cast<std::size_t>(receive_count[s]));
  // every round's total stays within an int
  const long long kChunk = std::max(1LL, (1LL << 30) / static_cast<long long>(size));
  for (long long offset = 0;; offset += kChunk) {
    std::vector<int> sc(size), sd(size), rc(size), rd(size);
    std::vector<char> send, receive;
    bool more = false;
    for (std::size_t q = 0; q < size; ++q) {
      const auto n = std::max(0LL, std::min(kChunk, send_count[q] - offset));
      sd[q] = static_cast<int>(send.size());
      sc[q] = static_cast<int>(n);
      if (n > 0)
        send.insert(send.end(), outgoing[q].begin() + offset, outgoing[q].begin() + offset + n);
      more = more || send_count[q] > offset + kChunk;
    }
    int receive_total = 0;
    for (std::size_t s = 0; s < size; ++s) {
      const auto n = std::max(0LL, std::min(kChunk, receive_count[s] - offset));
      rd[s] = receive_total;
      rc[s] = static_cast<int>(n);
      receive_total += rc[s];
      more = more || receive_count[s] > offset + kChunk;
    }
    receive.resize(static_cast<std::size_t>(receive_total));
    MPI_Alltoallv(send.data(), sc.data(), sd.data(), MPI_CHAR, receive.data(), rc.data(), rd.data(),
                  MPI_CHAR, raw);
    for (std::size_t s = 0; s < size; ++s)
      std::copy(receive.begin() + rd[s], receive.begin() + rd[s] + rc[s],
                received[s].begin() + offset);
    int any = more ? 1 : 0, all_any = 0;
    MPI_Allreduce(&any, &all_any, 1, MPI_INT, MPI_MAX, raw);
    if (!all_any) break;
  }
  return received;
}

}  // namespace efg
