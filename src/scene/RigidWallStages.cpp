#include "scene/RigidWallStages.hpp"

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

std::vector<std::string> check_rigid_wall_stages(const Scene& scene) {
  std::vector<std::string> warnings;
  if (scene.rigid_walls.empty() || scene.stages.empty()) return warnings;
  bool any_explicit = false;
  for (const auto& stage : scene.stages) any_explicit = any_explicit || stage.driver == "explicit";
  if (!any_explicit)
    throw InputError(schema::located_message(
        scene.file, scene.document["rigid_walls"][0], "rigid_walls[0]",
        "rigid wall '" + scene.rigid_walls.front().name +
            "' would never act: walls act in explicit stages only, and every stage of this scene "
            "is implicit (expected driver: explicit, or a rigid body with a contact, which "
            "implicit stages enforce)"));
  for (const auto& stage : scene.stages)
    if (stage.driver == "implicit")
      warnings.push_back("stage '" + stage.name + "' (implicit) runs without the rigid walls: " +
                         "walls act in explicit stages only (a rigid body with a contact acts in " +
                         "both)");
  return warnings;
}

}  // namespace efg
