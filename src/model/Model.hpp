// Everything a run knows before its first stage: the validated scene, the background mesh on
// every rank, the particle partition and the Tpetra maps. Built completely (and so every input
// error found) before any output file is touched.
#pragma once

#include "discretization/PartDiscretization.hpp"
#include "mesh/BackgroundMesh.hpp"
#include "parallel/DofMaps.hpp"
#include "parallel/NodePartition.hpp"
#include "scene/Scene.hpp"

namespace efg {

struct Model {
  Scene scene;
  BackgroundMesh mesh;
  NodePartition partition;                ///< ghosts: the union over parts
  std::vector<PartDiscretization> parts;  ///< one per scene part, in scene order
  DofMaps maps;
};

/// Reads the scene (rank 0 reads the file), loads or generates the mesh (rank 0) and checks them
/// against each other; throws InputError on every rank when anything is wrong.
Scene load_scene(const CommPtr& comm, const std::string& scene_file);
/// (On a shell surface read in 3D the scene's 3D probe and point-load points are projected onto
/// its chart: scene/ShellSurfacePoints.hpp.)
BackgroundMesh load_mesh(const CommPtr& comm, Scene& scene);

/// load_scene + load_mesh + partition + discretization of every part + maps (one displacement
/// dof per dimension). A numerical failure on any rank stops every rank.
Model build_model(const CommPtr& comm, const std::string& scene_file);
/// The same from an already parsed scene (tests build scenes from text).
Model build_model(const CommPtr& comm, Scene scene);

/// The Tpetra id of mesh node `node` in the model's node maps: the whole mesh's index (on a
/// rank's part of a distributed read the mesh's own indices are local).
inline GlobalOrdinal global_node_id(const Model& model, LocalIndex node) {
  return static_cast<GlobalOrdinal>(model.mesh.global_node(static_cast<std::size_t>(node)));
}

}  // namespace efg
