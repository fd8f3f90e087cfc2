#include "scene/PartFormulationCheck.hpp"

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

void check_part_formulations(const Scene& scene) {
  bool any_mixed = false;
  for (const auto& part : scene.parts)
    any_mixed = any_mixed || part.formulation == PartFormulation::mixed_up;
  for (std::size_t k = 0; k < scene.output.fields.size(); ++k)
    if (scene.output.fields[k] == "cell_pressure" && !any_mixed)
      throw InputError(schema::located_message(
          scene.file, scene.document["output"]["fields"][k],
          "output.fields[" + std::to_string(k) + "]",
          "cell_pressure is the pressure of mixed_up parts; no part has formulation: mixed_up"));
  for (std::size_t i = 0; i < scene.parts.size(); ++i) {
    const auto& part = scene.parts[i];
    if (part.formulation != PartFormulation::mixed_up) {
      if (const YAML::Node key = scene.document["parts"][i]["pressure_cells"]; key)
        throw InputError(schema::located_message(
            scene.file, key, "parts[" + std::to_string(i) + "].pressure_cells",
            "pressure_cells chooses the pressure of a mixed_up part; part '" + part.name +
                "' has formulation: displacement (expected formulation: mixed_up, or no "
                "pressure_cells)"));
      continue;
    }
    const auto* material = scene.find_material(part.material);
    if (!material) continue;  // reported by the part's own check
    const auto path = "parts[" + std::to_string(i) + "].formulation";
    const YAML::Node at = scene.document["parts"][i]["formulation"];
    // Every material model takes mixed_up: linear elastic and J2 through their deviatoric
    // constants, neo-Hookean through its isochoric part (model/MaterialLaws).
    if (material->youngs_modulus_field)
      throw InputError(schema::located_message(
          scene.file, at, path,
          "mixed_up takes one bulk modulus per part; material '" + material->name +
              "' has a graded youngs_modulus: expected a number"));
  }
}

}  // namespace efg
