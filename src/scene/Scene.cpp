// The scene's lookups and whole-scene properties (scene/Scene.hpp), apart from its reading.
#include "scene/Scene.hpp"

#include <algorithm>

namespace efg {

const CurveSpec* Scene::find_curve(const std::string& curve_name) const {
  for (const auto& c : curves)
    if (c.name == curve_name) return &c;
  return nullptr;
}

double Scene::largest_poissons_ratio() const {
  double largest = 0.0;
  for (const auto& part : parts) {
    const auto* material = find_material(part.material);
    if (!material) continue;
    const auto nu = material->constants.find("poissons_ratio");
    if (nu != material->constants.end()) largest = std::max(largest, nu->second);
  }
  return largest;
}

const MaterialSpec* Scene::find_material(const std::string& material_name) const {
  for (const auto& m : materials)
    if (m.name == material_name) return &m;
  return nullptr;
}

bool Scene::every_part_linear_elastic() const {
  for (const auto& part : parts) {
    const auto* material = find_material(part.material);
    if (material && material->model != "linear_elastic") return false;
  }
  return true;
}

}  // namespace efg
