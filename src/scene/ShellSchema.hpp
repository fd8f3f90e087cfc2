// Scene keys of shell parts (parts[].shell), rotation conditions (boundary_conditions[].rx, ry)
// and the shell pressure load; scene/ShellChecks cross-checks them against the rest of the scene.
#pragma once

#include <vector>

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr shell_spec();
/// rx, ry of a displacement condition.
std::vector<schema::Key> rotation_keys();
/// The keys of loads of type shell_pressure.
std::vector<schema::Key> shell_pressure_keys();

}  // namespace efg
