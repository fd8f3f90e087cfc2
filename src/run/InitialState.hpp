// Restart from a record of an earlier run (scene key initial_state): the generalized
// displacements and velocities of the particles and the committed history of path-dependent
// materials, as written by the output fields generalized_displacement, generalized_velocity and
// material_state. The forming run writes them, the springback run reads them (LS-DYNA's dynain
// file plays this role). Rigid bodies start from their scene state; the boundary points of
// transformation conditions start with a fresh history (as after any stage switch).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "drivers/RunState.hpp"
#include "mesh/BackgroundMesh.hpp"
#include "model/Model.hpp"
#include "operators/SolidOperator.hpp"
#include "parallel/Comm.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// The record initial_state names, with its nodal columns (name -> value per mesh node).
struct RestartRecord {
  double time = 0;
  std::map<std::string, std::vector<double>> nodal;
};

/// Reads and checks the record against the scene and mesh (same mesh, the restart columns
/// present, path-dependent parts integrated at particles, stages ending after the record's time).
/// Throws InputError at initial_state (file, line, key path); nothing when the scene has none.
/// Only the record's restart columns are read. On a rank's part of a distributed read (collective
/// then) each rank reads its slice of the file's nodes and fetches its part's nodes: the columns
/// are per node of the part.
std::optional<RestartRecord> read_initial_state(const CommPtr& comm, const Scene& scene,
                                                const BackgroundMesh& mesh);

/// Sets the state's d, v and time and the operators' committed material history from the record
/// (no-op without initial_state).
void apply_initial_state(const Model& model, const SolidOperator& op, RunState& state);

}  // namespace efg
