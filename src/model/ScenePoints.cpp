#include "model/ScenePoints.hpp"

#include <sstream>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "model/PointOwner.hpp"
#include "parallel/Collective.hpp"
#include "scene/SchemaValidator.hpp"

namespace efg {

void check_scene_points(const CommPtr& comm, const Model& model) {
  const auto& scene = model.scene;
  const auto check = [&](const double* point, const YAML::Node& key, const std::string& path,
                         const std::string& what) {
    const int part = evaluating_part(model, point);  // collective: before the check's agreement
    run_collectively(comm, [&] {
      if (part < 0) return;
      const auto& p = model.parts[static_cast<std::size_t>(part)];
      try {
        evaluate_shape_functions(p.cloud, point, 1, false, [&](std::size_t) { return what; });
      } catch (const NumericalError& e) {
        std::ostringstream o;
        o << "the point lies beyond the supports of part '" << p.part->name
          << "', whose particle is nearest (" << e.what() << "); expected a point inside a part";
        throw InputError(schema::located_message(scene.file, key, path, o.str()));
      }
    });
  };
  const auto& d = scene.document;
  for (std::size_t i = 0; i < scene.probes.size(); ++i)
    check(scene.probes[i].point.data(), d["probes"][i]["point"],
          "probes[" + std::to_string(i) + "].point", "probe '" + scene.probes[i].name + "'");
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    if (scene.loads[i].type == "shell_point_load")
      check(scene.loads[i].point.data(), d["loads"][i]["point"],
            "loads[" + std::to_string(i) + "].point", "load '" + scene.loads[i].name + "'");
}

}  // namespace efg
