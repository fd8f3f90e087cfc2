// Everything `efg run` validates before its first step that the scene and mesh checks do not:
// the output paths, the reference quantities of the verification block, the solver settings of
// the implicit stages. `efg check` calls the same function (one code path: the bad-scene corpus
// runs through both and must give the same message).
#pragma once

#include <string>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Throws InputError (file, line, key path) on every rank; creates and writes nothing.
void check_run_inputs(const CommPtr& comm, const Scene& scene, const BackgroundMesh& mesh,
                      const std::string& output_dir);

}  // namespace efg
