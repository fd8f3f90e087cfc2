#include "drivers/MassDamping.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "parallel/ReproducibleSum.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

MassDamping::MassDamping(const Vector& alpha, const Vector& mass)
    : alpha_(alpha, Teuchos::Copy),
      active_(alpha.normInf() > 0),
      mass_(mass),
      average_(mass.getMap()),
      momentum_(mass.getMap()) {}

void MassDamping::add_to_acceleration(const Vector& v, Vector& a) const {
  if (!active_) return;
  momentum_.elementWiseMultiply(1.0, alpha_, v, 0.0);
  a.update(-1.0, momentum_, 1.0);
}

void MassDamping::end_step(double dt, Vector& v, Vector& a) const {
  if (!active_) return;
  {
    const auto alpha = alpha_.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto vv = v.getLocalViewHost(Tpetra::Access::ReadWrite);
    auto aa = a.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t i = 0; i < vv.extent(0); ++i) {
      vv(i, 0) /= 1.0 + 0.5 * alpha(i, 0) * dt;
      aa(i, 0) -= alpha(i, 0) * vv(i, 0);
    }
  }
}

double MassDamping::work(double dt, const Vector& v_old, const Vector& v_new) const {
  if (!active_) return 0.0;
  average_.update(0.5, v_old, 0.5, v_new, 0.0);
  momentum_.elementWiseMultiply(1.0, mass_, average_, 0.0);
  momentum_.elementWiseMultiply(dt, alpha_, momentum_, 0.0);
  return reproducible_dot(momentum_, average_);
}

Vector mass_damping_of(const ModelOperators& ops, const StageSpec& stage) {
  const auto& model = ops.model();
  Vector alpha(model.maps.owned_dofs);  // zeros
  const double value = stage.settings["damping"].as<double>();
  std::vector<std::string> names;
  for (const auto& n : stage.settings["damping_parts"]) names.push_back(n.as<std::string>());
  for (const auto& name : names) {
    const bool known = std::any_of(model.parts.begin(), model.parts.end(),
                                   [&](const auto& d) { return d.part->name == name; });
    if (known) continue;
    std::size_t i = 0;
    while (i < model.scene.stages.size() && model.scene.stages[i].name != stage.name) ++i;
    const auto path = "stages[" + std::to_string(i) + "].damping_parts";
    throw InputError(schema::located_message(
        model.scene.file, model.scene.document["stages"][i]["damping_parts"], path,
        "no part named '" + name + "' (expected names of parts of the scene)"));
  }
  if (!(value > 0)) return alpha;
  const auto dim = static_cast<std::size_t>(model.mesh.dimension);
  const auto& owned = *model.maps.owned_dofs;
  const auto& overlap = *model.maps.overlap_dofs;
  auto view = alpha.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    if (!names.empty() &&
        std::find(names.begin(), names.end(), model.parts[p].part->name) == names.end())
      continue;
    for (const int node : ops.solid().overlap_node(p))
      for (std::size_t c = 0; c < dim; ++c) {
        const auto global = overlap.getGlobalElement(static_cast<int>(node * dim + c));
        const auto local = owned.getLocalElement(global);
        if (local != Teuchos::OrdinalTraits<int>::invalid())
          view(static_cast<std::size_t>(local), 0) = value;
      }
  }
  return alpha;
}

}  // namespace efg
