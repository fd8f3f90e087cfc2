// The mesh is read (or generated) once, on rank 0, and sent to every rank. A failure on rank 0
// is sent instead, so every rank throws the same InputError and exits with the same code.
#pragma once

#include <functional>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/Comm.hpp"

namespace efg {

/// Runs `load` on rank 0 and returns its mesh on every rank.
BackgroundMesh load_on_root_and_broadcast(const CommPtr& comm,
                                          const std::function<BackgroundMesh()>& load);

/// Byte (de)serialization used by the broadcast (exposed for tests).
std::vector<char> serialize(const BackgroundMesh& mesh);
BackgroundMesh deserialize(const std::vector<char>& bytes);

}  // namespace efg
