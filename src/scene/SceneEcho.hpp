// The resolved scene as it is echoed to the log and by `efg check`: lists of plain values in
// flow style ([0, 0, 1]) so the echo stays as short as a hand-written scene.
#pragma once

#include <yaml-cpp/yaml.h>

namespace efg {

YAML::Node compact_for_echo(const YAML::Node& resolved);

}  // namespace efg
