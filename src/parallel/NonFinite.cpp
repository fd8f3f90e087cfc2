#include "parallel/NonFinite.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>

namespace efg {

long long non_finite_dof(const Tpetra::Vector<>& a, const Tpetra::Vector<>* b) {
  const auto& map = *a.getMap();
  const auto x = a.getLocalViewHost(Tpetra::Access::ReadOnly);
  long long mine = -1, any = -1;
  if (b) {
    const auto y = b->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < x.extent(0) && mine < 0; ++k)
      if (!std::isfinite(x(k, 0)) || !std::isfinite(y(k, 0)))
        mine = map.getGlobalElement(static_cast<int>(k));
  } else {
    for (std::size_t k = 0; k < x.extent(0) && mine < 0; ++k)
      if (!std::isfinite(x(k, 0))) mine = map.getGlobalElement(static_cast<int>(k));
  }
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, mine, Teuchos::outArg(any));
  return any;
}

}  // namespace efg
