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
/// column_offset: characters right of the node's first one (an expression's faulty character).
std::string located_message(const std::string& file, const YAML::Node& node,
                            const std::string& path, const std::string& message,
                            int column_offset = 0);

/// Column offset of character `position` of an expression written as this scalar (quotes skipped).
int expression_column_offset(const YAML::Node& node, int position);

/// True when yaml-cpp reads `node` as an integer written otherwise than in plain decimal digits:
/// it takes 0x8 as 8 and 010 as octal 8 (the stream's base detection), which a reader expects
/// to be an error or ten.
bool is_non_decimal_integer(const YAML::Node& node);

}  // namespace efg::schema
