// Values written as expressions are checked where they will be used before anything runs: each
// is evaluated at the mesh nodes it applies to (a condition's or initial value's node set, a
// load's side-set nodes or its parts' nodes (a body force: the nodes of the parts it loads), every node for an exact solution) and, when it uses
// t, at 17 equally spaced times of every stage (start and end included). A value that is not finite there
// (a division by zero, the root or logarithm of a negative number) is an input error naming the
// file, line, column, key, the point and the time: `efg check` finds it.
#pragma once

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

void check_expressions_at_nodes(const Scene& scene, const BackgroundMesh& mesh);

}  // namespace efg
