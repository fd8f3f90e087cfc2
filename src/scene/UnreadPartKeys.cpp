#include "scene/UnreadPartKeys.hpp"

#include "scene/SchemaValidator.hpp"

namespace efg {

std::vector<std::string> unread_part_keys(const std::string& file, const YAML::Node& written,
                                          const YAML::Node& resolved, const std::string& path) {
  std::vector<std::string> out;
  const auto note = [&](const YAML::Node& at, const std::string& key, const std::string& why) {
    out.push_back(schema::located_message(file, at, path + "." + key, "ignored: " + why));
  };
  const auto integration = resolved["section"]["integration"].as<std::string>();
  if (const auto section = written["section"]; section && section.IsMap()) {
    if (section["gauss_order"] && integration != "gauss")
      note(section["gauss_order"], "section.gauss_order",
           "only integration gauss reads it, and this part's integration is " + integration);
    if (section["smoothing_quadrature"] && (integration == "gauss" || integration == "nodal"))
      note(section["smoothing_quadrature"], "section.smoothing_quadrature",
           "only integration scni and scni_subcells read it, and this part's integration is " +
               integration);
  }
  return out;
}

}  // namespace efg
