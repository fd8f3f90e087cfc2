// Writes the scene reference (docs/scene.md) from the schema.
#pragma once

#include <string>

#include "scene/Schema.hpp"

namespace efg::schema {

/// A Markdown document: one table per map, every key with type, default, unit, range and meaning.
std::string markdown(const Spec& root, const std::string& title);

}  // namespace efg::schema
