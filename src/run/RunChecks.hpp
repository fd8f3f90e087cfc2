// Everything `efg run` validates before its first step that the scene and mesh checks do not:
// the output paths, the reference quantities of the verification block, the solver settings of
// the implicit stages. `efg check` calls the same function (one code path: the bad-scene corpus
// runs through both and must give the same message).
#pragma once

#include <string>

#include "mesh/BackgroundMesh.hpp"
#include "model/Model.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError (file, line, key path) on every rank; creates and writes nothing.
/// `partition`: the owners of `mesh`'s nodes, needed when it is a rank's part of a mesh read in
/// slices (sizes are then summed over the ranks).
void check_run_inputs(const CommPtr& comm, const Scene& scene, const BackgroundMesh& mesh,
                      const std::string& output_dir, const NodePartition* partition = nullptr);

/// For `efg check`: what `run` finds once the model is built and before its first step, from the
/// same code: the operators (conditions, loads, walls) and each explicit stage's time-step plan
/// (a fixed dt above the stable one, a stage needing more than 1e10 steps).
void check_model_setup(const CommPtr& comm, const Model& model);

}  // namespace efg
