// Guards on the raw YAML of a scene, before any pass walks it: one document per file (found by
// scanning the text: YAML::LoadAll loops forever on some malformed input, yaml-cpp issue 1040),
// syntax errors located, a node budget against alias bombs ("billion laughs"), UTF-8 text
// without control characters, and no explicit tags ('!!binary').
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace efg {

/// Parses `text` as one YAML document; throws InputError naming `file`, line and column.
YAML::Node load_single_document(const std::string& text, const std::string& file);

}  // namespace efg
