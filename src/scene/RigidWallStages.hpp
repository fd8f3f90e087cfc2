// Rigid walls act in explicit stages only (the implicit driver has no wall term). A scene whose
// stages are all implicit has walls that can never act: refused. A scene mixing both (an explicit
// crush, then an implicit springback without the walls) is valid and told which stages run
// without them: before, the walls were dropped silently in implicit stages (issue 55, item 7).
#pragma once

#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError at rigid_walls[0] when no stage is explicit; otherwise returns one warning
/// per implicit stage that runs without the walls (none when there are no walls).
std::vector<std::string> check_rigid_wall_stages(const Scene& scene);

}  // namespace efg
