#include "contact/FacingArea.hpp"

#include "discretization/SmoothingFacets.hpp"

namespace efg {

std::vector<SideShares> part_side_shares(const Model& model, std::size_t p) {
  const auto& mesh = model.mesh;
  const auto& part = *model.parts[p].part;
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  const double thickness = dim == 2 ? part.thickness : 1.0;
  std::vector<SideShares> shares(mesh.node_count());
  auto X = [&](LocalIndex n, std::size_t k) {
    return mesh.coordinates[static_cast<std::size_t>(n) * dim + k];
  };
  for (const auto& [cell, side] : boundary_sides(mesh, part.blocks)) {
    const auto nodes = mesh.side_node_indices(cell, side);
    // The side's area vector (its measure along its normal; the sign does not matter here):
    // 2D the segment turned by 90 degrees x thickness, 3D Newell's sum over its polygon.
    std::array<double, 3> a{0, 0, 0};
    if (dim == 2) {
      a[0] = (X(nodes[1], 1) - X(nodes[0], 1)) * thickness;
      a[1] = -(X(nodes[1], 0) - X(nodes[0], 0)) * thickness;
    } else {
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const auto m = nodes[i], n = nodes[(i + 1) % nodes.size()];
        a[0] += 0.5 * (X(m, 1) * X(n, 2) - X(m, 2) * X(n, 1));
        a[1] += 0.5 * (X(m, 2) * X(n, 0) - X(m, 0) * X(n, 2));
        a[2] += 0.5 * (X(m, 0) * X(n, 1) - X(m, 1) * X(n, 0));
      }
    }
    const double each = 1.0 / static_cast<double>(nodes.size());
    for (auto n : nodes)
      shares[static_cast<std::size_t>(n)].push_back({a[0] * each, a[1] * each, a[2] * each});
  }
  return shares;
}

}  // namespace efg
