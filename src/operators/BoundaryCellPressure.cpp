#include "operators/BoundaryCellPressure.hpp"

#include <algorithm>

namespace efg {

BoundaryCellPressure attach_cell_pressure(const CellAverages& row, const PartDiscretization& d,
                                          const std::vector<int>& overlap_node,
                                          const MaterialLaw& law, std::vector<int>& nodes,
                                          std::vector<double>& phi, std::vector<double>& grad) {
  const auto udim = static_cast<std::size_t>(d.cloud.dimension);
  BoundaryCellPressure c;
  c.kappa = law.bulk_modulus;
  c.kappa0 = relieved_bulk_modulus(c.kappa, law.elastic.mu);
  c.finite = d.part->section.formulation != Formulation::small_strain;
  c.bbar.assign(nodes.size() * udim, 0.0);
  for (std::size_t k = 0; k < row.gradients.particles.size(); ++k) {
    const int node = overlap_node[static_cast<std::size_t>(row.gradients.particles[k])];
    auto at = std::find(nodes.begin(), nodes.end(), node);
    if (at == nodes.end()) {  // reached by the cell, not by the point
      nodes.push_back(node);
      phi.push_back(0.0);
      grad.insert(grad.end(), udim, 0.0);
      c.bbar.insert(c.bbar.end(), udim, 0.0);
      at = nodes.end() - 1;
    }
    const auto e = static_cast<std::size_t>(at - nodes.begin());
    for (std::size_t i = 0; i < udim; ++i)
      c.bbar[e * udim + i] = row.gradients.values[k * udim + i];
  }
  return c;
}

}  // namespace efg
