#include "mesh/NodalVolume.hpp"

#include <algorithm>

namespace efg {

std::vector<double> lumped_nodal_volumes(const BackgroundMesh& mesh,
                                         const std::vector<std::string>& blocks) {
  std::vector<double> volume(mesh.node_count(), 0.0);
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  for (const auto& b : mesh.blocks) {
    if (!blocks.empty() && std::find(blocks.begin(), blocks.end(), b.name) == blocks.end())
      continue;
    const auto npc = static_cast<std::size_t>(cell_node_count(b.type));
    std::vector<double> x(npc * dim);
    for (std::size_t c = 0; c < b.cell_count(); ++c) {
      for (std::size_t a = 0; a < npc; ++a)
        for (std::size_t d = 0; d < dim; ++d)
          x[a * dim + d] =
              mesh.coordinates[static_cast<std::size_t>(b.connectivity[c * npc + a]) * dim + d];
      const double share = cell_geometry(b.type, x.data()).volume / static_cast<double>(npc);
      for (std::size_t a = 0; a < npc; ++a)
        volume[static_cast<std::size_t>(b.connectivity[c * npc + a])] += share;
    }
  }
  return volume;
}

}  // namespace efg
