#include "discretization/CellSmoothing.hpp"

#include <algorithm>
#include <array>

#include "core/Errors.hpp"
#include "discretization/CellSides.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "discretization/SmoothingFacets.hpp"

namespace efg {
namespace {

// Cells whose boundary points are evaluated together: bounds the shape function tables.
constexpr std::size_t kCellBatch = 2048;

struct CellBoundary {
  std::size_t group = 0, cell = 0;
  std::vector<SmoothingPoint> points;
};

}  // namespace

CellAverages cell_averages(const BackgroundMesh& mesh, const ParticleCloud& cloud,
                           const PressureCells& groups, const std::vector<std::size_t>& list) {
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  std::vector<CellBoundary> cells;
  for (const auto g : list) {
    CellBoundary cb;
    cb.group = g;
    cb.cell = groups.cells[groups.offsets[g]];
    // The group's outer sides (a single cell's: all of them, in side order).
    const auto first = groups.cells.begin() + static_cast<std::ptrdiff_t>(groups.offsets[g]);
    const auto last = groups.cells.begin() + static_cast<std::ptrdiff_t>(groups.offsets[g + 1]);
    const auto sides = outer_sides(mesh, std::vector<std::size_t>(first, last));
    for (const auto& [global_cell, s] : sides) {
      const auto nodes = mesh.side_node_indices(global_cell, s);
      std::vector<std::array<double, 3>> x(nodes.size(), {0, 0, 0});
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (std::size_t d = 0; d < dim; ++d)
          x[a][d] = mesh.coordinates[static_cast<std::size_t>(nodes[a]) * dim + d];
      const auto side = side_smoothing_points(x, nodes, cloud.dimension);
      cb.points.insert(cb.points.end(), side.begin(), side.end());
    }
    cells.push_back(std::move(cb));
  }

  CellAverages out;
  out.gradients.width = cloud.dimension;
  out.gradients.offsets.assign(1, 0);
  std::vector<double> sum(cloud.size() * dim, 0.0);  // scratch: one cell's row, by particle
  std::vector<char> touched(cloud.size(), 0);
  const auto index = index_cloud(cloud);  // searched by every batch (docs/scaling.md)
  for (std::size_t first = 0; first < cells.size(); first += kCellBatch) {
    const std::size_t last = std::min(cells.size(), first + kCellBatch);
    std::vector<double> coords;
    std::vector<std::size_t> cell_of_point;
    for (std::size_t c = first; c < last; ++c)
      for (const auto& p : cells[c].points) {
        coords.insert(coords.end(), p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(dim));
        cell_of_point.push_back(cells[c].cell);
      }
    const auto phi = evaluate_shape_functions(
        index, cloud, coords.data(), cell_of_point.size(), false, [&](std::size_t p) {
          return "boundary point of cell " + std::to_string(cell_of_point[p] + 1) +
                 " (mixed u-p cell average)";
        });
    std::size_t point = 0;
    for (std::size_t c = first; c < last; ++c) {
      const auto& cb = cells[c];
      // V_c = 1/dim sum (x - x0) . n w: the closed boundary's sum n w vanishes, so the shift to
      // the first point only removes cancellation.
      std::array<double, 3> x0{}, centroid{};
      for (std::size_t d = 0; d < dim; ++d) x0[d] = cb.points.front().x[d];
      double volume = 0;
      for (const auto& p : cb.points)
        for (std::size_t d = 0; d < dim; ++d) {
          volume += (p.x[d] - x0[d]) * p.weighted_normal[d] / static_cast<double>(dim);
          centroid[d] += p.x[d] / static_cast<double>(cb.points.size());
        }
      if (!(volume > 0))
        throw NumericalError("mixed u-p: pressure cell of background cell " +
                             std::to_string(cb.cell + 1) + " has volume " + std::to_string(volume) +
                             " <= 0");
      std::vector<LocalIndex> row;
      for (const auto& p : cb.points) {
        for (auto k = phi.neighbors.offsets[point]; k < phi.neighbors.offsets[point + 1]; ++k) {
          const auto i = static_cast<std::size_t>(phi.neighbors.particles[k]);
          if (!touched[i]) {
            touched[i] = 1;
            row.push_back(static_cast<LocalIndex>(i));
          }
          for (std::size_t d = 0; d < dim; ++d)
            sum[i * dim + d] += phi.phi[k] * p.weighted_normal[d];
        }
        ++point;
      }
      std::sort(row.begin(), row.end());
      for (auto i : row) {
        const auto k = static_cast<std::size_t>(i);
        out.gradients.particles.push_back(i);
        for (std::size_t d = 0; d < dim; ++d) {
          out.gradients.values.push_back(sum[k * dim + d] / volume);
          sum[k * dim + d] = 0;
        }
        touched[k] = 0;
      }
      out.gradients.offsets.push_back(out.gradients.particles.size());
      out.group.push_back(cb.group);
      out.cell.push_back(cb.cell);
      out.volume.push_back(volume);
      out.centroid.insert(out.centroid.end(), centroid.begin(),
                          centroid.begin() + static_cast<std::ptrdiff_t>(dim));
    }
  }
  return out;
}

}  // namespace efg
