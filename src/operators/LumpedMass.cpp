#include "operators/LumpedMass.hpp"

#include "core/Errors.hpp"
#include "discretization/GatherIndex.hpp"

namespace efg {
namespace {

// m_I += rho sum_q w_q phi_I(x_q) (row-sum lumping of the consistent mass, which the partition
// of unity makes exact for the total mass), gathered per particle I in ascending point order.
struct MassKernel {
  int dim = 3;
  GatherIndex by_node;
  DeviceView<const double*> weight;  // rho x quadrature weight per point
  DeviceView<const double*> phi;     // per entry
  Kokkos::View<double**, Kokkos::LayoutLeft, MemSpace> m;

  KOKKOS_INLINE_FUNCTION void operator()(const std::size_t n) const {
    double mass = 0.0;
    for (auto e = by_node.offsets(n); e < by_node.offsets(n + 1); ++e) {
      const auto k = by_node.entry(e);
      mass += weight(static_cast<std::size_t>(by_node.row_of_entry(k))) * phi(k);
    }
    for (int i = 0; i < dim; ++i)
      m(n * static_cast<std::size_t>(dim) + static_cast<std::size_t>(i), 0) += mass;
  }
};

}  // namespace

Vector lumped_mass(const ModelOperators& ops) {
  const auto& model = ops.model();
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  Vector m_overlap(model.maps.overlap_dofs), m(model.maps.owned_dofs);
  const auto nodes = model.maps.overlap_nodes->getNodeNumElements();
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    const auto* material = model.scene.find_material(part.part->material);
    if (!material->density)
      throw InputError(model.scene.file + ": material '" + material->name +
                       "' needs a density for an explicit stage");
    const double rho = *material->density * (udim == 2 ? part.part->thickness : 1.0);
    const auto& ip = part.points;
    std::vector<double> weight(ip.weight);
    for (auto& w : weight) w *= rho;
    std::vector<int> node(ip.values.particles.size());
    for (std::size_t k = 0; k < node.size(); ++k)
      node[k] = ops.solid().overlap_node(p)[static_cast<std::size_t>(ip.values.particles[k])];
    MassKernel kernel;
    kernel.dim = model.mesh.dimension;
    kernel.by_node = gather_index(to_device(ip.values.offsets, "efg::mass offsets"),
                                  to_device(node, "efg::mass nodes"), nodes);
    kernel.weight = to_device(weight, "efg::mass weights");
    kernel.phi = to_device(ip.values.values, "efg::mass phi");
    kernel.m = m_overlap.getLocalViewDevice(Tpetra::Access::ReadWrite);
    Kokkos::parallel_for("efg::lumped_mass", Kokkos::RangePolicy<ExecSpace>(0, nodes), kernel);
  }
  ops.to_owned(m_overlap, m);
  const auto mv = m.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < mv.extent(0); ++k)
    if (!(mv(k, 0) > 0))
      throw NumericalError(
          "lumped mass of particle " +
          std::to_string(model.maps.owned_dofs->getGlobalElement(static_cast<int>(k)) /
                             static_cast<long long>(udim) +
                         1) +
          " is " + std::to_string(mv(k, 0)) +
          " (expected > 0): its shape function integrates to a negative value; "
          "raise the part's dilation");
  return m;
}

}  // namespace efg
