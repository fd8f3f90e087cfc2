// Solver sublists of a scene (passthrough maps) become Teuchos::ParameterLists for NOX, Belos,
// Ifpack2 and MueLu, which validate them against their own valid parameters when used.
#pragma once

#include <yaml-cpp/yaml.h>
#include <Teuchos_ParameterList.hpp>

#include <string>

namespace efg {

/// Scalars become bool (true/false), int, double or string in that order of preference; maps
/// become sublists; lists of numbers become Teuchos::Array<double>, lists of text Array<string>.
/// Throws InputError (with `file`, line and `path`) on anything else (e.g. a list of maps).
Teuchos::ParameterList parameter_list_from_yaml(const YAML::Node& map, const std::string& name,
                                                const std::string& file, const std::string& path);

}  // namespace efg
