#include "scene/StageLists.hpp"

#include <set>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/Suggest.hpp"

namespace efg {

void check_stage_list(const Scene& scene, const std::vector<std::string>& names,
                      const ActiveStages& list, const char* section, std::size_t i) {
  std::set<std::string> seen;
  for (std::size_t k = 0; k < list.names.size(); ++k) {
    const auto& name = list.names[k];
    const auto path =
        std::string(section) + "[" + std::to_string(i) + "].stages[" + std::to_string(k) + "]";
    const YAML::Node at = scene.document[section][i]["stages"][k];
    if (!seen.insert(name).second)
      throw InputError(
          schema::located_message(scene.file, at, path, "stage '" + name + "' is named twice"));
    bool found = false;
    for (const auto& n : names) found = found || n == name;
    if (found) continue;
    std::string message = "no stage named '" + name + "'";
    if (auto guess = closest_match(name, names)) message += " (did you mean '" + *guess + "'?)";
    std::string all;
    for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
    message += "; stages: " + (all.empty() ? std::string("none") : all);
    throw InputError(schema::located_message(scene.file, at, path, message));
  }
}

void check_stage_lists(const Scene& scene, const std::vector<std::string>& stage_names) {
  for (std::size_t i = 0; i < scene.boundary_conditions.size(); ++i)
    check_stage_list(scene, stage_names, scene.boundary_conditions[i].stages, "boundary_conditions",
                     i);
  for (std::size_t i = 0; i < scene.loads.size(); ++i)
    check_stage_list(scene, stage_names, scene.loads[i].stages, "loads", i);
}

}  // namespace efg
