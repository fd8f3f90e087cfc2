#include "model/GradedMaterials.hpp"

#include <algorithm>

namespace efg {

void set_graded_references(Scene& scene, const BackgroundMesh& mesh) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  for (auto& m : scene.materials) {
    if (!m.youngs_modulus_field) continue;
    double largest = 0;
    for (const auto& part : scene.parts) {
      if (part.material != m.name) continue;
      for (const auto& b : mesh.blocks) {
        if (std::find(part.blocks.begin(), part.blocks.end(), b.name) == part.blocks.end())
          continue;
        for (auto n : b.connectivity) {
          double X[3] = {0, 0, 0};
          for (std::size_t k = 0; k < dim; ++k)
            X[k] = mesh.coordinates[static_cast<std::size_t>(n) * dim + k];
          largest = std::max(largest, m.youngs_modulus_field->at(X, 0.0));
        }
      }
    }
    m.constants["youngs_modulus"] = largest;
  }
}

std::vector<double> modulus_scale(const MaterialSpec& material, const double* x, std::size_t count,
                                  int dimension) {
  std::vector<double> scale;
  if (!material.youngs_modulus_field) return scale;
  const auto dim = static_cast<std::size_t>(dimension);
  const double reference = material.constants.at("youngs_modulus");
  scale.resize(count);
  for (std::size_t q = 0; q < count; ++q) {
    double X[3] = {0, 0, 0};
    for (std::size_t k = 0; k < dim; ++k) X[k] = x[q * dim + k];
    scale[q] = material.youngs_modulus_field->at(X, 0.0) / reference;
  }
  return scale;
}

}  // namespace efg
