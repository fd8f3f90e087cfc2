// Scene keys of shell parts (parts[].shell), rotation conditions (boundary_conditions[].rx, ry)
// and the shell loads (pressure, edge line loads); scene/ShellChecks cross-checks them against the rest of the scene.
#pragma once

#include <vector>

#include "scene/Schema.hpp"

namespace efg {

schema::SpecPtr shell_spec();
/// rx, ry of a displacement condition.
std::vector<schema::Key> rotation_keys();
/// The keys of loads of type shell_pressure.
std::vector<schema::Key> shell_pressure_keys();
/// The keys of loads of type shell_edge_load (line forces and moments on an edge).
std::vector<schema::Key> shell_edge_load_keys();
/// The keys of loads of type shell_point_load (a force and moment at a point).
std::vector<schema::Key> shell_point_load_keys();

}  // namespace efg
