// Checks between a scene and its mesh: names of blocks and sets exist, vectors have the mesh's
// dimension, every block belongs to at most one part.
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError naming the scene file, line, key path and the names the mesh does have.
void check_scene_against_mesh(const Scene& scene, const BackgroundMesh& mesh);

}  // namespace efg
