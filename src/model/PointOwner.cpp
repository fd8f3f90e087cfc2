#include "model/PointOwner.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <limits>

namespace efg {

int evaluating_part(const Model& model, const double* point) {
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  double best = std::numeric_limits<double>::max();
  int best_part = -1;
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    for (std::size_t j = 0; j < model.parts[p].cloud.owned_count; ++j) {
      double d2 = 0;
      for (std::size_t k = 0; k < udim; ++k) {
        const double e = model.parts[p].cloud.x(j)[k] - point[k];
        d2 += e * e;
      }
      if (d2 < best) {
        best = d2;
        best_part = static_cast<int>(p);
      }
    }
  const auto& comm = *model.maps.owned_dofs->getComm();
  double global_best = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, best, Teuchos::outArg(global_best));
  const int candidate = best == global_best ? comm.getRank() : comm.getSize();
  int winner = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, candidate, Teuchos::outArg(winner));
  return comm.getRank() == winner ? best_part : -1;
}

}  // namespace efg
