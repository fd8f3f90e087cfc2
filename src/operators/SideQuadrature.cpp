#include "operators/SideQuadrature.hpp"

#include <algorithm>
#include <cmath>

#include "discretization/SmoothingFacets.hpp"

namespace efg {

std::vector<SidePoint> side_quadrature(const BackgroundMesh& mesh, std::size_t cell, int side) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  const auto nodes = mesh.side_node_indices(cell, side);
  std::vector<std::array<double, 3>> x(nodes.size(), {0, 0, 0});
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (std::size_t d = 0; d < dim; ++d)
      x[a][d] = mesh.coordinates[static_cast<std::size_t>(nodes[a]) * dim + d];
  std::vector<SidePoint> out;
  for (const auto& s : side_smoothing_points(x, nodes, mesh.dimension)) {
    SidePoint p;
    p.x = s.x;
    p.weight = std::sqrt(s.weighted_normal[0] * s.weighted_normal[0] +
                         s.weighted_normal[1] * s.weighted_normal[1] +
                         s.weighted_normal[2] * s.weighted_normal[2]);
    for (std::size_t d = 0; d < 3; ++d) p.normal[d] = s.weighted_normal[d] / p.weight;
    out.push_back(p);
  }
  return out;
}

NodeSetSides node_set_sides(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                            const std::vector<char>& in_set, const std::vector<int>& owner,
                            int rank) {
  NodeSetSides out;
  for (const auto& [cell, side] : boundary_sides(mesh, blocks)) {
    const auto nodes = mesh.side_node_indices(cell, side);
    if (!std::all_of(nodes.begin(), nodes.end(),
                     [&](LocalIndex n) { return in_set[static_cast<std::size_t>(n)] != 0; }))
      continue;
    const auto first = *std::min_element(nodes.begin(), nodes.end());
    if (owner[static_cast<std::size_t>(first)] == rank) out.here.emplace_back(cell, side);
  }
  return out;
}

}  // namespace efg
