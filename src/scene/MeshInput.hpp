// Reads mesh: from the validated scene: an Exodus file's path (checked readable), or the built-in
// generator's box with its further blocks (mesh.more_blocks), cross-checked beyond the schema
// (entries per dimension, corners in order, the coordinate map, block names and dimensions).
#pragma once

#include "scene/Scene.hpp"

namespace efg {

/// Fills scene.mesh_file or scene.generator and scene.more_blocks from scene.resolved; throws
/// InputError at file:line:col and key path for the first problem.
void read_mesh_input(Scene& scene);

}  // namespace efg
