#include "scene/SceneAngles.hpp"

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/Suggest.hpp"

namespace efg {

void read_angle_input(Scene& scene) {
  std::vector<std::string> probes;
  for (const auto& p : scene.probes) probes.push_back(p.name);
  const auto& resolved = scene.resolved["angles"];
  for (std::size_t i = 0; i < resolved.size(); ++i) {
    AngleSpec spec;
    spec.name = resolved[i]["name"].as<std::string>();
    spec.from = resolved[i]["from"].as<std::string>();
    spec.to = resolved[i]["to"].as<std::string>();
    const auto path = "angles[" + std::to_string(i) + "].";
    auto fail = [&](const char* key, const std::string& message) {
      throw InputError(schema::located_message(scene.file, scene.document["angles"][i][key],
                                               path + key, message));
    };
    for (const char* key : {"from", "to"}) {
      const auto name = resolved[i][key].as<std::string>();
      if (std::find(probes.begin(), probes.end(), name) != probes.end()) continue;
      const auto close = closest_match(name, probes);
      fail(key, "expected the name of a probe (probes:); found '" + name + "'" +
                    (close ? " (did you mean '" + *close + "'?)" : std::string()));
    }
    if (spec.from == spec.to)
      fail("to", "expected a probe other than from ('" + spec.from + "'): a segment needs two");
    scene.angles.push_back(spec);
  }
}

double segment_angle_degrees(const std::array<double, 3>& from, const std::array<double, 3>& to,
                             const std::array<double, 2>& u_from,
                             const std::array<double, 2>& u_to) {
  const double dx = to[0] + u_to[0] - from[0] - u_from[0];
  const double dy = to[1] + u_to[1] - from[1] - u_from[1];
  return std::atan2(dy, dx) * 180.0 / M_PI;
}

}  // namespace efg
