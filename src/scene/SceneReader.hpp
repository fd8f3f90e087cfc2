// Reads a scene file: YAML syntax, schema validation, typed scene, checks between its sections.
#pragma once

#include <string>

#include "scene/Scene.hpp"

namespace efg {

/// Parses and validates scene text; `file` names it in messages and anchors relative paths.
/// Throws InputError (file, line, key path, what was expected).
Scene parse_scene(const std::string& text, const std::string& file);

/// Reads the file, then parse_scene(). Throws InputError when it cannot be read.
std::string read_scene_text(const std::string& file);

}  // namespace efg
