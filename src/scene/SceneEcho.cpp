#include "scene/SceneEcho.hpp"

namespace efg {
namespace {
void compact(YAML::Node node) {
  if (node.IsSequence()) {
    bool scalars = true;
    for (const auto& item : node) scalars = scalars && item.IsScalar();
    if (scalars) node.SetStyle(YAML::EmitterStyle::Flow);
  }
  if (node.IsMap() && node.size() == 0) node.SetStyle(YAML::EmitterStyle::Flow);
  if (node.IsSequence() || node.IsMap())
    for (auto it = node.begin(); it != node.end(); ++it) compact(node.IsMap() ? it->second : *it);
}
}  // namespace

YAML::Node compact_for_echo(const YAML::Node& resolved) {
  YAML::Node copy = YAML::Clone(resolved);
  compact(copy);
  return copy;
}

}  // namespace efg
