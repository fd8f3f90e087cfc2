#include "model/MaterialStates.hpp"

#include "model/GradedMaterials.hpp"

namespace efg {

MaterialStates::MaterialStates(const Model& model) {
  for (const auto& d : model.parts) {
    PartStates s;
    s.law = material_law(model.scene, *d.part, model.mesh.dimension);
    const MaterialLaw& law = s.law;
    s.count = law.state_count();
    const auto scale = modulus_scale(*model.scene.find_material(d.part->material),
                                     d.points.x.data(), d.points.size(), model.mesh.dimension);
    if (!scale.empty()) {
      s.modulus_scale = DeviceView<double*>("efg::modulus scale", scale.size());
      auto host = Kokkos::create_mirror_view(s.modulus_scale);
      for (std::size_t q = 0; q < scale.size(); ++q) host(q) = scale[q];
      Kokkos::deep_copy(s.modulus_scale, host);
    }
    if (s.count > 0) {
      const std::size_t points = d.points.size(), count = static_cast<std::size_t>(s.count);
      s.committed = DeviceView<double**>("efg::history committed", points, count);
      s.trial = DeviceView<double**>("efg::history trial", points, count);
      auto host = Kokkos::create_mirror_view(s.committed);
      double initial[physics::j2_state::count];
      law.initial_state(initial);
      for (std::size_t q = 0; q < points; ++q)
        for (std::size_t c = 0; c < count; ++c) host(q, c) = initial[c];
      Kokkos::deep_copy(s.committed, host);
      Kokkos::deep_copy(s.trial, host);
    }
    parts_.push_back(s);
  }
}

bool MaterialStates::any() const {
  for (const auto& s : parts_)
    if (s.count > 0) return true;
  return false;
}

void MaterialStates::commit() {
  for (auto& s : parts_)
    if (s.count > 0) Kokkos::deep_copy(s.committed, s.trial);
}

}  // namespace efg
