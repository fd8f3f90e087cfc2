// The schema of efg scene files: the single description from which scenes are validated and
// docs/scene.md is generated (`efg schema`).
#pragma once

#include "scene/Schema.hpp"

namespace efg {

/// The root map of a scene file.
const schema::Spec& scene_schema();

}  // namespace efg
