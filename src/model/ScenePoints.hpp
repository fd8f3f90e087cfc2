// Points a scene names in space (probes, shell point loads): each is evaluated by the rank owning
// the particle nearest to it (model/PointOwner.hpp), with the shape functions of that particle's
// part there. A point that no particle supports of that part cover (beyond the part's surface,
// in a gap between parts) is bad input: said at setup, by every rank, at the point's key (exit
// 2), not found at the first record as a numerical failure on the evaluating rank alone while
// the other ranks wait in the record's reduction (before: exit 3 on one rank, an MPI abort on
// several).
#pragma once

#include "model/Model.hpp"

namespace efg {

/// Throws InputError at probes[i].point or loads[i].point (shell_point_load) for the first point
/// whose evaluating part's supports do not cover it. Collective.
void check_scene_points(const CommPtr& comm, const Model& model);

}  // namespace efg
