#include "discretization/ScniGradients.hpp"

#include <algorithm>

#include "discretization/GatherIndex.hpp"

namespace efg {
namespace {

// One work item per domain L (an owned particle's, or a piece of it): sums sign * phi_I(x_p) * n_p over L's smoothing points p
// (sign -1 where L is the point's `minus` side) into L's row, then divides by V_L.
template <int Dim>
struct SmoothedGradientKernel {
  GatherIndex points_of;  // slot 2p (plus side) or 2p + 1 (minus side) per particle
  DeviceView<const std::size_t*> phi_offsets;  // neighbours of every smoothing point
  DeviceView<const int*> phi_particle;
  DeviceView<const double*> phi;
  DeviceView<const double**> normal;           // weighted normal of every smoothing point
  DeviceView<const LocalIndex*> global_id;     // of every cloud particle
  DeviceView<const std::size_t*> row_offsets;  // rows of B~, particles by ascending global id
  DeviceView<const LocalIndex*> row_gid;
  DeviceView<const double*> volume;  // V_L per row
  DeviceView<double**> value;        // B~ per row entry

  KOKKOS_INLINE_FUNCTION void operator()(const std::size_t l) const {
    const auto begin = row_offsets(l), end = row_offsets(l + 1);
    for (auto e = points_of.offsets(l); e < points_of.offsets(l + 1); ++e) {
      const auto slot = points_of.entry(e);
      const auto p = slot / 2;
      const double sign = slot % 2 == 0 ? 1.0 : -1.0;
      for (auto k = phi_offsets(p); k < phi_offsets(p + 1); ++k) {
        // The row holds every neighbour of L's points: binary search by global id.
        const auto gid = global_id(phi_particle(k));
        auto lo = begin, hi = end;
        while (hi - lo > 1) {
          const auto mid = lo + (hi - lo) / 2;
          if (row_gid(mid) <= gid)
            lo = mid;
          else
            hi = mid;
        }
        for (int d = 0; d < Dim; ++d)
          value(lo, static_cast<std::size_t>(d)) +=
              sign * phi(k) * normal(p, static_cast<std::size_t>(d));
      }
    }
    for (auto k = begin; k < end; ++k)
      for (int d = 0; d < Dim; ++d) value(k, static_cast<std::size_t>(d)) /= volume(l);
  }
};

template <int Dim>
void run(const SmoothedGradientKernel<Dim>& kernel, std::size_t rows) {
  Kokkos::parallel_for("efg::scni_gradients", Kokkos::RangePolicy<ExecSpace>(0, rows), kernel);
}

}  // namespace

CsrTable smoothed_gradients(const ParticleCloud& cloud, const std::vector<SmoothingPoint>& points,
                            const ShapeFunctionValues& phi,
                            const std::vector<LocalIndex>& row_index,
                            const std::vector<double>& row_volume,
                            DeviceView<const LocalIndex*> global_id) {
  if (global_id.extent(0) != cloud.size())
    global_id = to_device(cloud.mesh_node, "efg::scni global ids");
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  const auto owned = row_volume.size();
  // Slots 2p and 2p + 1 name the particles on either side of point p; sides that are not rows
  // here go to a discarded column `owned` (= rows).
  std::vector<int> side(2 * points.size());
  std::vector<std::size_t> slot_offsets(2 * points.size() + 1);
  for (std::size_t p = 0; p < points.size(); ++p) {
    for (int s = 0; s < 2; ++s) {
      const auto node = s == 0 ? points[p].plus : points[p].minus;
      const auto l = node < 0 ? -1 : row_index[static_cast<std::size_t>(node)];
      side[2 * p + static_cast<std::size_t>(s)] = l < 0 ? static_cast<int>(owned) : l;
    }
  }
  for (std::size_t k = 0; k < slot_offsets.size(); ++k) slot_offsets[k] = k;
  const auto points_of = gather_index(to_device(slot_offsets, "efg::scni slots"),
                                      to_device(side, "efg::scni sides"), owned + 1);

  // Row structure on the host: the neighbours of L's points, by ascending global id.
  const auto of_offsets = to_host(points_of.offsets);
  const auto of_entry = to_host(points_of.entry);
  CsrTable table;
  table.width = cloud.dimension;
  table.offsets.assign(1, 0);
  std::vector<LocalIndex> row;
  std::vector<LocalIndex> row_gid;
  // Each particle appears in the lists of many of L's points (some 700 entries for 60 distinct
  // particles in 3D): marked on first sight, so only the distinct ones are sorted.
  std::vector<char> seen(cloud.size(), 0);
  auto by_gid = [&](LocalIndex a, LocalIndex b) {
    return cloud.mesh_node[static_cast<std::size_t>(a)] <
           cloud.mesh_node[static_cast<std::size_t>(b)];
  };
  for (std::size_t l = 0; l < owned; ++l) {
    row.clear();
    for (auto e = of_offsets[l]; e < of_offsets[l + 1]; ++e) {
      const auto p = of_entry[e] / 2;
      for (auto k = phi.neighbors.offsets[p]; k < phi.neighbors.offsets[p + 1]; ++k) {
        const auto i = phi.neighbors.particles[k];
        if (seen[static_cast<std::size_t>(i)]) continue;
        seen[static_cast<std::size_t>(i)] = 1;
        row.push_back(i);
      }
    }
    for (auto i : row) seen[static_cast<std::size_t>(i)] = 0;
    std::sort(row.begin(), row.end(), by_gid);
    for (auto i : row) {
      table.particles.push_back(i);
      row_gid.push_back(cloud.mesh_node[static_cast<std::size_t>(i)]);
    }
    table.offsets.push_back(table.particles.size());
  }

  std::vector<double> normal(points.size() * dim);
  for (std::size_t p = 0; p < points.size(); ++p)
    for (std::size_t d = 0; d < dim; ++d) normal[p * dim + d] = points[p].weighted_normal[d];
  std::vector<int> phi_particle(phi.neighbors.particles.begin(), phi.neighbors.particles.end());
  DeviceView<double**> value("efg::scni gradient", table.particles.size(), dim);
  auto fill = [&](auto kernel) {
    kernel.points_of = points_of;
    kernel.phi_offsets = to_device(phi.neighbors.offsets, "efg::scni phi offsets");
    kernel.phi_particle = to_device(phi_particle, "efg::scni phi particles");
    kernel.phi = to_device(phi.phi, "efg::scni phi");
    kernel.normal = to_device(normal.data(), points.size(), dim, "efg::scni normals");
    kernel.global_id = global_id;
    kernel.row_offsets = to_device(table.offsets, "efg::scni row offsets");
    kernel.row_gid = to_device(row_gid, "efg::scni row ids");
    kernel.volume = to_device(row_volume, "efg::scni volumes");
    kernel.value = value;
    run(kernel, owned);
  };
  switch (cloud.dimension) {
    case 1:
      fill(SmoothedGradientKernel<1>{});
      break;
    case 2:
      fill(SmoothedGradientKernel<2>{});
      break;
    default:
      fill(SmoothedGradientKernel<3>{});
      break;
  }
  table.values = to_host(value);
  return table;
}

}  // namespace efg
