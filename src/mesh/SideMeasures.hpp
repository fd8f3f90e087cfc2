// Sizes of a boundary side of the background mesh, given by its nodes in order around it: the
// length of its longest edge (the h of boundary penalties: Nitsche's beta, contact stiffness) and
// its measure (length in 2D, area in 3D as a fan of triangles).
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

double side_longest_edge(const BackgroundMesh& mesh, const std::vector<LocalIndex>& nodes);
double side_measure(const BackgroundMesh& mesh, const std::vector<LocalIndex>& nodes);

}  // namespace efg
