#include "contact/SurfaceFacets.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "contact/FacetProjection.hpp"
#include "discretization/SmoothingFacets.hpp"

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

SurfaceFacets surface_facets(const Model& model, const std::vector<std::string>& parts) {
  const auto& mesh = model.mesh;
  const int dim = mesh.dimension;
  SurfaceFacets s;
  s.nodes_per_facet = dim == 2 ? 2 : 3;
  std::vector<std::string> blocks;
  for (const auto& part : model.scene.parts)
    if (std::find(parts.begin(), parts.end(), part.name) != parts.end())
      blocks.insert(blocks.end(), part.blocks.begin(), part.blocks.end());
  std::vector<std::vector<LocalIndex>> facets;  // mesh nodes, outward ordered
  std::vector<char> on_surface(mesh.node_count(), 0);
  for (const auto& [cell, side] : boundary_sides(mesh, blocks)) {
    const auto nodes = mesh.side_node_indices(cell, side);
    for (auto n : nodes) on_surface[static_cast<std::size_t>(n)] = 1;
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
    for (auto& piece : pieces) {
      double x[3][3] = {};
      for (std::size_t a = 0; a < piece.size(); ++a) {
        const auto at = node_x(mesh, piece[a]);
        std::copy(at.begin(), at.end(), x[a]);
      }
      double n[3];
      contact::facet_normal(x, dim, n);
      double out = 0;
      for (std::size_t k = 0; k < 3; ++k) out += (x[0][k] - centroid[k]) * n[k];
      if (out < 0) std::swap(piece[0], piece[1]);
      double longest = 0;
      for (std::size_t a = 0; a < piece.size(); ++a)
        for (std::size_t b = a + 1; b < piece.size(); ++b) {
          double len2 = 0;
          for (std::size_t k = 0; k < 3; ++k) len2 += (x[a][k] - x[b][k]) * (x[a][k] - x[b][k]);
          longest = std::max(longest, std::sqrt(len2));
        }
      s.reference_size.push_back(longest);
      facets.push_back(piece);
    }
  }
  std::vector<int> surface_index(mesh.node_count(), -1);
  for (std::size_t n = 0; n < mesh.node_count(); ++n)
    if (on_surface[n]) {
      surface_index[n] = static_cast<int>(s.mesh_node.size());
      s.mesh_node.push_back(static_cast<LocalIndex>(n));
    }
  for (const auto& f : facets)
    for (auto n : f) s.facet.push_back(surface_index[static_cast<std::size_t>(n)]);
  return s;
}

}  // namespace efg
