// Scene values that may vary in space and time, read from the validated document: a number or an
// expression compiled with the scene's parameters (src/expressions), each remembering where it
// was written; and the user exact solution built from them (verification.user_solution).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

/// `resolved`: the validated value (a number, or expression text); `doc`: the node as written.
ScalarField read_field(const Scene& scene, const YAML::Node& resolved, const YAML::Node& doc,
                       const std::string& path, ExpressionVariables variables);
/// The same for each entry of a list (paths path[i]).
std::vector<ScalarField> read_fields(const Scene& scene, const YAML::Node& resolved,
                                     const YAML::Node& doc, const std::string& path,
                                     ExpressionVariables variables);

/// scene.user_solution from verification (resolved) / doc; user_solution must be given exactly
/// when exact_solution is user (InputError otherwise).
void read_user_solution(Scene& scene, const YAML::Node& verification, const YAML::Node& doc);

}  // namespace efg
