// Personalized all-to-all: each rank hands one list per destination rank and receives the lists
// addressed to it, one per source rank (MPI_Alltoallv with the counts exchanged first). The
// distributed mesh read routes nodes, cells and set entries with it (parallel/LocalMesh.hpp).
// The lists travel in one flat buffer each way: what is sent is released as it is packed, so a
// list exists at most twice (packed and received) rather than once per copy.
#pragma once

#include <cstring>
#include <type_traits>
#include <vector>

#include "parallel/Comm.hpp"

namespace efg {

/// Lists of bytes back to back: list q is bytes [offset(q), offset(q) + counts[q]).
struct PackedLists {
  std::vector<char> bytes;
  std::vector<long long> counts;
};

/// Sends list q of `outgoing` to rank q; returns the lists received, list s from rank s.
PackedLists exchange_packed(const CommPtr& comm, PackedLists outgoing);

/// The same for lists of a trivially copyable type; `outgoing` is consumed.
template <class T>
std::vector<std::vector<T>> all_to_all(const CommPtr& comm, std::vector<std::vector<T>> outgoing) {
  static_assert(std::is_trivially_copyable_v<T>, "all_to_all sends raw bytes");
  PackedLists send;
  std::size_t total = 0;
  for (const auto& list : outgoing) total += list.size() * sizeof(T);
  send.bytes.resize(total);
  std::size_t at = 0;
  for (auto& list : outgoing) {
    const auto n = list.size() * sizeof(T);
    if (n > 0) std::memcpy(send.bytes.data() + at, list.data(), n);
    at += n;
    send.counts.push_back(static_cast<long long>(n));
    std::vector<T>().swap(list);  // released as packed
  }
  const auto received = exchange_packed(comm, std::move(send));
  std::vector<std::vector<T>> result(received.counts.size());
  at = 0;
  for (std::size_t s = 0; s < result.size(); ++s) {
    const auto n = static_cast<std::size_t>(received.counts[s]);
    result[s].resize(n / sizeof(T));
    if (n > 0) std::memcpy(result[s].data(), received.bytes.data() + at, n);
    at += n;
  }
  return result;
}

/// Every rank's list, concatenated in rank order, on every rank (lists small beside the mesh:
/// a contact surface, a tool's cells).
template <class T>
std::vector<T> all_gather(const CommPtr& comm, const std::vector<T>& mine) {
  std::vector<T> all;
  for (const auto& list : all_to_all(
           comm, std::vector<std::vector<T>>(static_cast<std::size_t>(comm->getSize()), mine)))
    all.insert(all.end(), list.begin(), list.end());
  return all;
}

}  // namespace efg
