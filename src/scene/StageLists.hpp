// The `stages:` lists of boundary conditions and loads: which stages each acts in. A springback
// stage is an implicit stage that leaves out the conditions (and tools) that formed the part.
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Every name in a stages list is one of `stage_names` (the scene's stages), named once. Throws
/// InputError at file:line:col and key path (with a "did you mean") otherwise. The lists of the
/// boundary conditions and loads:
void check_stage_lists(const Scene& scene, const std::vector<std::string>& stage_names);
/// One list, of entry i of `section` (e.g. "contacts").
void check_stage_list(const Scene& scene, const std::vector<std::string>& stage_names,
                      const ActiveStages& list, const char* section, std::size_t i);

}  // namespace efg
