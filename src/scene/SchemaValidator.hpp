// Checks a parsed YAML document against a schema::Spec and returns the resolved document: the
// same values with every default filled in, keys in schema order. The first problem found is
// thrown as InputError "FILE:LINE:COL: key path: what was expected, what was found".
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "scene/Schema.hpp"

namespace efg::schema {

YAML::Node validate(const YAML::Node& document, const Spec& spec, const std::string& file);

/// "FILE:LINE:COL: PATH: MESSAGE" for a node of a parsed document (line and column 1-based).
std::string located_message(const std::string& file, const YAML::Node& node,
                            const std::string& path, const std::string& message);

}  // namespace efg::schema
