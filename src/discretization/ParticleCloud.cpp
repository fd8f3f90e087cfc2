#include "discretization/ParticleCloud.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/NodalVolume.hpp"

namespace efg {

std::vector<LocalIndex> nodes_of_blocks(const BackgroundMesh& mesh,
                                        const std::vector<std::string>& blocks) {
  std::vector<char> in(mesh.node_count(), 0);
  for (const auto& b : mesh.blocks)
    if (std::find(blocks.begin(), blocks.end(), b.name) != blocks.end())
      for (auto n : b.connectivity) in[static_cast<std::size_t>(n)] = 1;
  std::vector<LocalIndex> nodes;
  for (std::size_t n = 0; n < in.size(); ++n)
    if (in[n]) nodes.push_back(static_cast<LocalIndex>(n));
  return nodes;
}

namespace {

/// Spacing along axis d of a cell whose edges may be sheared against the axes: the largest |e_d|
/// over the cell's edges e that run mainly along d (|e_d| the largest of e's components, ties
/// included); the cell's extent in d if none does. On a lattice of sheared cells this is the
/// distance between the rows of nodes along d, where the cell's extent also counts the shear of
/// the edges running along the other axes: on Cook's panel at 16 x 16 cells the extent in y
/// reaches 3.75 node rows at the loaded end, the supports then span 7.5 rows, and the wide,
/// smooth shape functions leave hundreds of nodal modes nearly without strain energy
/// (generalized eigenvalues against the background cells' finite elements down to 3e-7, where an
/// axis-aligned rectangle's stay above 0.01: multigrid then stalls, docs/implicit.md).
double edge_spacing(const BackgroundMesh& mesh, const LocalIndex* cell,
                    const std::vector<std::array<int, 2>>& edges, std::size_t d, double extent) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  double spacing = -1;
  for (const auto& edge : edges) {
    const double* x0 = &mesh.coordinates[static_cast<std::size_t>(cell[edge[0]]) * dim];
    const double* x1 = &mesh.coordinates[static_cast<std::size_t>(cell[edge[1]]) * dim];
    double largest = 0;
    for (std::size_t k = 0; k < dim; ++k) largest = std::max(largest, std::abs(x1[k] - x0[k]));
    const double along = std::abs(x1[d] - x0[d]);
    if (along > 0 && along >= largest * (1 - 1e-12)) spacing = std::max(spacing, along);
  }
  return spacing < 0 ? extent : spacing;
}

}  // namespace

std::vector<double> support_sizes(const BackgroundMesh& mesh,
                                  const std::vector<std::string>& blocks,
                                  const SectionSpec& section) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::vector<double> h(mesh.node_count() * dim, 0.0);
  for (const auto& b : mesh.blocks) {
    if (std::find(blocks.begin(), blocks.end(), b.name) == blocks.end()) continue;
    const auto npc = static_cast<std::size_t>(cell_node_count(b.type));
    const auto edges = cell_edges(b.type);
    for (std::size_t c = 0; c < b.cell_count(); ++c) {
      const auto* cell = &b.connectivity[c * npc];
      for (std::size_t d = 0; d < dim; ++d) {
        double lo = mesh.coordinates[static_cast<std::size_t>(cell[0]) * dim + d], hi = lo;
        for (std::size_t a = 1; a < npc; ++a) {
          const double x = mesh.coordinates[static_cast<std::size_t>(cell[a]) * dim + d];
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
        const double along_edges = section.spacing == SpacingMeasure::edges
                                       ? edge_spacing(mesh, cell, edges, d, hi - lo)
                                       : 0;
        for (std::size_t a = 0; a < npc; ++a) {
          const auto node = static_cast<std::size_t>(cell[a]);
          double spacing = hi - lo;
          if (section.spacing == SpacingMeasure::neighbors) {
            const double xi = mesh.coordinates[node * dim + d];
            spacing = std::max(std::abs(hi - xi), std::abs(xi - lo));
          } else if (section.spacing == SpacingMeasure::edges) {
            spacing = along_edges;
          }
          h[node * dim + d] = std::max(h[node * dim + d], spacing);
        }
      }
    }
  }
  std::vector<double> a(h.size(), 0.0);
  std::vector<double> part_max(dim, 0.0);
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    double hmax = 0;
    for (std::size_t d = 0; d < dim; ++d) hmax = std::max(hmax, h[n * dim + d]);
    for (std::size_t d = 0; d < dim; ++d) {
      const double dilation =
          section.dilation.size() == 1 ? section.dilation[0] : section.dilation[d];
      a[n * dim + d] =
          section.support == SupportShape::sphere ? dilation * hmax : dilation * h[n * dim + d];
      part_max[d] = std::max(part_max[d], a[n * dim + d]);
    }
  }
  if (section.per_part_support) {
    // (a rank's part of a mesh holds part of the part: its maximum comes over all ranks)
    if (!section.part_support.empty()) part_max = section.part_support;
    for (std::size_t n = 0; n < mesh.node_count(); ++n)
      if (h[n * dim] > 0)
        for (std::size_t d = 0; d < dim; ++d) a[n * dim + d] = part_max[d];
  }
  return a;
}

double extent_over_rows(const BackgroundMesh& mesh, const std::vector<std::string>& blocks) {
  SectionSpec measure;
  measure.dilation = {1.0};
  measure.spacing = SpacingMeasure::cells;
  const auto extents = support_sizes(mesh, blocks, measure);
  measure.spacing = SpacingMeasure::edges;
  const auto rows = support_sizes(mesh, blocks, measure);
  double ratio = 1.0;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (rows[k] > 0) ratio = std::max(ratio, extents[k] / rows[k]);
  return ratio;
}

ParticleCloud make_particle_cloud(const BackgroundMesh& mesh, const PartSpec& part,
                                  const std::vector<int>& owner, int rank,
                                  const std::vector<LocalIndex>& ghost_nodes) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  const auto nodes = nodes_of_blocks(mesh, part.blocks);
  std::vector<char> in_part(mesh.node_count(), 0);
  for (auto n : nodes) in_part[static_cast<std::size_t>(n)] = 1;
  const auto a = support_sizes(mesh, part.blocks, part.section);
  const auto volume = lumped_nodal_volumes(mesh, part.blocks);

  ParticleCloud cloud;
  cloud.dimension = mesh.dimension;
  cloud.section = part.section;
  auto add = [&](LocalIndex node) {
    const auto n = static_cast<std::size_t>(node);
    cloud.mesh_node.push_back(node);
    for (std::size_t d = 0; d < dim; ++d) {
      cloud.position.push_back(mesh.coordinates[n * dim + d]);
      cloud.support.push_back(a[n * dim + d]);
    }
    cloud.volume.push_back(volume[n]);
  };
  for (auto node : nodes)
    if (owner[static_cast<std::size_t>(node)] == rank) add(node);
  cloud.owned_count = cloud.size();
  for (auto node : ghost_nodes)
    if (in_part[static_cast<std::size_t>(node)] && owner[static_cast<std::size_t>(node)] != rank)
      add(node);
  return cloud;
}

double largest_support_reach(const ParticleCloud& cloud) {
  double largest = 0;
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  const bool sphere = cloud.section.support == SupportShape::sphere;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    for (std::size_t d = 0; d < (sphere ? 1 : dim); ++d)
      largest = std::max(largest, cloud.support[i * dim + d]);
  return largest;
}

}  // namespace efg
