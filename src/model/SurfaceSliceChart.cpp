#include "model/SurfaceSliceChart.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>

#include "core/Errors.hpp"
#include "mesh/SurfaceChart.hpp"
#include "parallel/Collective.hpp"
#include "parallel/SliceLookup.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

bool is_surface_slice(const Scene& scene, const MeshSlice& slice) {
  if (!scene.has_shells() || slice.dimension != 3 || slice.blocks.empty()) return false;
  return std::all_of(slice.blocks.begin(), slice.blocks.end(),
                     [](const BlockSlice& b) { return is_surface_cell(b.type); });
}

namespace {

/// Calls f(global cell, block, a, b, c) with the corners' positions for the triangles of every
/// cell of the slice (a quad as (0 1 2), (0 2 3), as mesh/SurfaceChart splits it).
template <class F>
void for_each_slice_triangle(const MeshSlice& slice, const std::vector<GlobalIndex>& ids,
                             const std::vector<double>& x, F&& f) {
  const auto at = [&](GlobalIndex g) {
    const auto i = std::lower_bound(ids.begin(), ids.end(), g) - ids.begin();
    return x.data() + 3 * i;
  };
  for (const auto& block : slice.blocks) {
    const auto n = static_cast<std::size_t>(cell_node_count(block.type));
    for (std::size_t c = 0; c < block.read_count(); ++c) {
      const auto* k = &block.connectivity[c * n];
      const auto cell = static_cast<std::size_t>(block.first_read) + c;
      f(cell, block, at(k[0]), at(k[1]), at(k[2]));
      if (n == 4) f(cell, block, at(k[0]), at(k[2]), at(k[3]));
    }
  }
}

}  // namespace

std::vector<double> chart_surface_slice(const CommPtr& comm, const Scene& scene, MeshSlice& slice,
                                        SurfaceProjection& plane) {
  // the corners of this slice's cells, from their slice holders
  std::vector<GlobalIndex> ids;
  for (const auto& block : slice.blocks)
    ids.insert(ids.end(), block.connectivity.begin(), block.connectivity.end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto corners = fetch_from_slices(comm, slice.node_count, 3, slice.coordinates, ids);
  // twice the area-weighted normal and the centroid, summed over the slices
  double sums[6] = {0, 0, 0, 0, 0, 0}, total[6] = {0, 0, 0, 0, 0, 0};
  for_each_slice_triangle(
      slice, ids, corners,
      [&](std::size_t, const BlockSlice&, const double* a, const double* b, const double* c) {
        const auto n = triangle_normal(a, b, c);
        for (std::size_t k = 0; k < 3; ++k) sums[k] += n[k];
      });
  const auto nodes = slice.read_node_count();
  for (std::size_t i = 0; i < nodes; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      sums[3 + k] += slice.coordinates[3 * i + k] / static_cast<double>(slice.node_count);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 6, sums, total);
  plane = projection_from({total[0], total[1], total[2]}, {total[3], total[4], total[5]});
  if (!scene.surface_chart)
    run_collectively(comm, [&] {
      for_each_slice_triangle(
          slice, ids, corners,
          [&](std::size_t cell, const BlockSlice& block, const double* a, const double* b,
              const double* c) { check_chart_triangle(plane, cell, block.name, a, b, c); });
    });
  auto positions = std::move(slice.coordinates);
  slice.coordinates.assign(2 * nodes, 0.0);
  for (std::size_t i = 0; i < nodes; ++i) {
    if (scene.surface_chart) {
      scene.surface_chart(&positions[3 * i], &slice.coordinates[2 * i]);
    } else {
      const auto xy = chart_coordinates(plane, &positions[3 * i]);
      slice.coordinates[2 * i] = xy[0];
      slice.coordinates[2 * i + 1] = xy[1];
    }
  }
  slice.dimension = 2;
  return positions;
}

void refuse_chart_without_surface(const Scene& scene) {
  throw InputError(schema::located_message(
      scene.file, scene.document["mesh"]["chart"], "mesh.chart",
      "a chart is for a shell surface read in 3D (SHELL4 or TRISHELL3 cells, shell parts); "
      "this mesh is none: expected no chart"));
}

}  // namespace efg
