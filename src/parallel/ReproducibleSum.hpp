// Sums whose value does not depend on the number of threads. Kokkos' parallel_reduce (and so
// Tpetra's dot and norm2) adds in an order that follows the thread count. The explicit driver's
// stable time step feeds norms into a finite-difference power iteration, where a last-bit
// difference moved dt by ~3e-11 relative and, through wall contact, the whole trajectory (1e-11
// of the velocity scale between 1 and 2 threads); its energy account subtracts nearly equal
// energies. Here every block of `block_size` terms is summed in index order by one work item (in
// parallel), and the block sums are added in block order on the host, then over ranks: the same
// bits on any thread count (a rank count still changes the order, as everywhere in Tpetra).
#pragma once

#include <Teuchos_Comm.hpp>
#include <Tpetra_Vector.hpp>

#include <vector>

#include "core/DeviceArrays.hpp"

namespace efg {

inline constexpr std::size_t block_size = 1024;

/// sum_{k < n} term(k) on this rank, in a thread-count-independent order.
template <class Term>
double block_sum(std::size_t n, const Term& term) {
  const std::size_t blocks = (n + block_size - 1) / block_size;
  DeviceView<double*> partial(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::block sums"),
                              blocks);
  Kokkos::parallel_for(
      "efg::block_sum", Kokkos::RangePolicy<ExecSpace>(0, blocks),
      KOKKOS_LAMBDA(const std::size_t b) {
        double s = 0.0;
        const std::size_t end = (b + 1) * block_size < n ? (b + 1) * block_size : n;
        for (std::size_t k = b * block_size; k < end; ++k) s += term(k);
        partial(b) = s;
      });
  double total = 0.0;
  for (const double s : to_host(partial)) total += s;
  return total;
}

/// The sum over ranks of this rank's `local`.
double sum_over_ranks(const Teuchos::Comm<int>& comm, double local);

/// a . b over all ranks.
double reproducible_dot(const Tpetra::Vector<>& a, const Tpetra::Vector<>& b);
/// ||v||_2 over all ranks.
double reproducible_norm2(const Tpetra::Vector<>& v);

}  // namespace efg
