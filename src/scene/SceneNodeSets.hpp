// Node sets made by the scene (node_sets:): the nodes inside a box, of the whole mesh or of one
// of its node sets. Added to the mesh beside its own sets, so every key naming a node set (a
// condition, a load, an initial value, the history) can name them.
#pragma once

#include <functional>

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Fills scene.node_sets from the resolved document (validated by the schema).
void read_node_set_input(Scene& scene);

/// Appends the scene's node sets to mesh.node_sets (ids after the mesh's largest). Throws
/// InputError at file:line:col and key path for a name the mesh already has, an unknown
/// `within`, corners of the wrong dimension or inverted, and a box that holds no node. On a
/// rank's part of a mesh (read in slices) a box may hold none of the part's nodes:
/// `held_anywhere(held here)` answers whether any rank's part holds one (a reduction, called
/// once per scene node set on every rank, in the same order).
void add_scene_node_sets(const Scene& scene, BackgroundMesh& mesh,
                         const std::function<bool(bool)>& held_anywhere = {});

}  // namespace efg
