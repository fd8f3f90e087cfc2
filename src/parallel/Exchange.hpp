// Personalized all-to-all: each rank hands one list per destination rank and receives the lists
// addressed to it, one per source rank (MPI_Alltoallv with the counts exchanged first). The
// distributed mesh read routes nodes, cells and set entries with it (parallel/LocalMesh.hpp).
#pragma once

#include <cstring>
#include <type_traits>
#include <vector>

#include "parallel/Comm.hpp"

namespace efg {

/// Bytes version: outgoing[q] goes to rank q; the result's [s] came from rank s.
std::vector<std::vector<char>> exchange_bytes(const CommPtr& comm,
                                              const std::vector<std::vector<char>>& outgoing);

/// The same for lists of a trivially copyable type.
template <class T>
std::vector<std::vector<T>> all_to_all(const CommPtr& comm,
                                       const std::vector<std::vector<T>>& outgoing) {
  static_assert(std::is_trivially_copyable_v<T>, "exchange sends raw bytes");
  std::vector<std::vector<char>> bytes(outgoing.size());
  for (std::size_t q = 0; q < outgoing.size(); ++q) {
    bytes[q].resize(outgoing[q].size() * sizeof(T));
    if (!bytes[q].empty()) std::memcpy(bytes[q].data(), outgoing[q].data(), bytes[q].size());
  }
  const auto received = exchange_bytes(comm, bytes);
  std::vector<std::vector<T>> result(received.size());
  for (std::size_t s = 0; s < received.size(); ++s) {
    result[s].resize(received[s].size() / sizeof(T));
    if (!result[s].empty()) std::memcpy(result[s].data(), received[s].data(), received[s].size());
  }
  return result;
}

}  // namespace efg
