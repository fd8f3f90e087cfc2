#include "run/InitialConditions.hpp"

namespace efg {

void apply_initial_conditions(const Model& model, RunState& state) {
  const int dim = model.mesh.dimension;
  for (const auto& ic : model.scene.initial_conditions) {
    auto& target = ic.type == "velocity" ? state.v : state.d;
    auto view = target.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (auto node : model.mesh.find_node_set(ic.node_set)->nodes) {
      if (model.partition.owner[static_cast<std::size_t>(node)] != model.partition.rank) continue;
      double X[3] = {0, 0, 0};
      for (int k = 0; k < dim; ++k)
        X[k] = model.mesh.coordinates[static_cast<std::size_t>(node * dim + k)];
      for (int i = 0; i < dim; ++i) {
        const auto row =
            model.maps.owned_dofs->getLocalElement(global_node_id(model, node) * dim + i);
        // The generalized value takes the value at the particle (as LS-DYNA's EFG nodal values).
        view(static_cast<std::size_t>(row), 0) = ic.value[static_cast<std::size_t>(i)].at(X, 0.0);
      }
    }
  }
}

}  // namespace efg
