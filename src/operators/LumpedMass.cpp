#include "operators/LumpedMass.hpp"

#include "core/Errors.hpp"

namespace efg {

Vector lumped_mass(const ModelOperators& ops) {
  const auto& model = ops.model();
  const auto udim = static_cast<std::size_t>(model.mesh.dimension);
  Vector m_overlap(model.maps.overlap_dofs), m(model.maps.owned_dofs);
  {
    auto mv = m_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      const auto* material = model.scene.find_material(part.part->material);
      if (!material->density)
        throw InputError(model.scene.file + ": material '" + material->name + "' needs a density for an explicit stage");
      const double rho = *material->density * (udim == 2 ? part.part->thickness : 1.0);
      const auto& ip = part.points;
      for (std::size_t q = 0; q < ip.size(); ++q)
        for (auto k = ip.values.offsets[q]; k < ip.values.offsets[q + 1]; ++k) {
          const auto n = static_cast<std::size_t>(ops.solid().overlap_node(p)[static_cast<std::size_t>(ip.values.particles[k])]);
          for (std::size_t i = 0; i < udim; ++i) mv(n * udim + i, 0) += rho * ip.weight[q] * ip.values.values[k];
        }
    }
  }
  ops.to_owned(m_overlap, m);
  const auto mv = m.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < mv.extent(0); ++k)
    if (!(mv(k, 0) > 0))
      throw NumericalError("lumped mass of particle " + std::to_string(model.maps.owned_dofs->getGlobalElement(static_cast<int>(k)) / static_cast<long long>(udim) + 1) +
                           " is " + std::to_string(mv(k, 0)) + " (expected > 0): its shape function integrates to a negative value; "
                           "raise the part's dilation");
  return m;
}

}  // namespace efg
