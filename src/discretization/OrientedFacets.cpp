#include "discretization/OrientedFacets.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "discretization/SmoothingFacets.hpp"
#include "geometry/FacetNormal.hpp"

namespace efg {

namespace {

std::array<double, 3> node_x(const BackgroundMesh& mesh, LocalIndex n) {
  std::array<double, 3> x{};
  for (int k = 0; k < mesh.dimension; ++k)
    x[static_cast<std::size_t>(k)] =
        mesh.coordinates[static_cast<std::size_t>(n) * static_cast<std::size_t>(mesh.dimension) +
                         static_cast<std::size_t>(k)];
  return x;
}

}  // namespace

OrientedFacets oriented_boundary_facets(const BackgroundMesh& mesh,
                                        const std::vector<std::string>& blocks) {
  const int dim = mesh.dimension;
  OrientedFacets s;
  s.nodes_per_facet = dim == 2 ? 2 : 3;
  for (const auto& [cell, side] : boundary_sides(mesh, blocks)) {
    const auto nodes = mesh.side_node_indices(cell, side);
    // The cell's centroid: the outward side of its facets.
    const auto [block, local] = mesh.locate_cell(cell);
    const auto per_cell = static_cast<std::size_t>(cell_node_count(block->type));
    std::array<double, 3> centroid{};
    for (std::size_t a = 0; a < per_cell; ++a) {
      const auto x = node_x(mesh, block->connectivity[local * per_cell + a]);
      for (std::size_t k = 0; k < 3; ++k) centroid[k] += x[k] / static_cast<double>(per_cell);
    }
    std::vector<std::vector<LocalIndex>> pieces;
    if (dim == 2 || nodes.size() == 3)
      pieces.push_back(nodes);
    else  // quadrilateral side: two triangles along the 0-2 diagonal
      pieces = {{nodes[0], nodes[1], nodes[2]}, {nodes[0], nodes[2], nodes[3]}};
    for (std::size_t which = 0; which < pieces.size(); ++which) {
      auto& piece = pieces[which];
      s.origin.push_back({cell, static_cast<std::size_t>(side), which});
      double x[3][3] = {};
      for (std::size_t a = 0; a < piece.size(); ++a) {
        const auto at = node_x(mesh, piece[a]);
        std::copy(at.begin(), at.end(), x[a]);
      }
      double n[3];
      facet_normal(x, dim, n);
      double out = 0;
      for (std::size_t k = 0; k < 3; ++k) out += (x[0][k] - centroid[k]) * n[k];
      if (out < 0) std::swap(piece[0], piece[1]);
      s.reference_size.push_back(longest_edge(x, static_cast<int>(piece.size())));
      s.nodes.insert(s.nodes.end(), piece.begin(), piece.end());
    }
  }
  return s;
}

}  // namespace efg
