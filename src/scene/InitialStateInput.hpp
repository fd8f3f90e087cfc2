// The initial_state key of a scene: the results file of an earlier run to restart from.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Fills scene.initial_state from the resolved document: the file relative to the scene's
/// folder, which must be readable, and the record time. Throws InputError at file:line:col.
void read_initial_state_input(Scene& scene);

}  // namespace efg
