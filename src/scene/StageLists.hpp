// The `stages:` lists of boundary conditions and loads: which stages each acts in. A springback
// stage is an implicit stage that leaves out the conditions (and tools) that formed the part.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Every name in a stages list is one of `stage_names` (the scene's stages), named once. Throws
/// InputError at file:line:col and key path (with a "did you mean") otherwise.
void check_stage_lists(const Scene& scene, const std::vector<std::string>& stage_names);

}  // namespace efg
