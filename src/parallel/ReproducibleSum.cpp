#include "parallel/ReproducibleSum.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>

namespace efg {

double sum_over_ranks(const Teuchos::Comm<int>& comm, double local) {
  double total = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, local, Teuchos::outArg(total));
  return total;
}

double reproducible_dot(const Tpetra::Vector<>& a, const Tpetra::Vector<>& b) {
  const auto x = a.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto y = b.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const double mine = block_sum(
      x.extent(0), KOKKOS_LAMBDA(const std::size_t k) { return x(k, 0) * y(k, 0); });
  return sum_over_ranks(*a.getMap()->getComm(), mine);
}

double reproducible_norm2(const Tpetra::Vector<>& v) {
  return std::sqrt(reproducible_dot(v, v));
}

}  // namespace efg
