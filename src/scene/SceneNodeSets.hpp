// Node sets made by the scene (node_sets:): the nodes inside a box, of the whole mesh or of one
// of its node sets. Added to the mesh beside its own sets, so every key naming a node set (a
// condition, a load, an initial value, the history) can name them.
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Fills scene.node_sets from the resolved document (validated by the schema).
void read_node_set_input(Scene& scene);

/// Appends the scene's node sets to mesh.node_sets (ids after the mesh's largest). Throws
/// InputError at file:line:col and key path for a name the mesh already has, an unknown
/// `within`, corners of the wrong dimension or inverted, and a box that holds no node.
void add_scene_node_sets(const Scene& scene, BackgroundMesh& mesh);

}  // namespace efg
