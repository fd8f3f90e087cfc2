// The global quantities of every output record (Exodus global variables and the CSV history):
// time step, energies and the energy balance error, strain energy, rigid wall forces, reactions
// of the boundary conditions, and the mean displacement and velocity of the history node sets.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "drivers/RunState.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

/// The global quantity names a scene's records carry, in record order (at most 32 characters).
std::vector<std::string> history_names(const Scene& scene, int dimension);

class RunHistory {
 public:
  explicit RunHistory(const Model& model);

  /// Names in record order (Exodus: at most 32 characters each).
  const std::vector<std::string>& names() const { return names_; }
  std::string csv_header() const;

  /// Collective. `reactions`: one per boundary condition (empty without an implicit stage).
  std::vector<double> values(const ModelOperators& ops, const RunState& state,
                             const Vector& d_overlap, const Vector& v_overlap,
                             const std::vector<std::array<double, 3>>& reactions) const;

 private:
  const Model& model_;
  std::vector<std::string> names_;
};

}  // namespace efg
