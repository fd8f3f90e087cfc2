// The solid blocks of a rigid body with their nodes at the same place welded into one (plain
// code, no Trilinos). A generated round body keeps two nodes where its map closes on itself -
// a tube mapped from a box [r0, r1] x [0, 2 pi] has its cells at angle 0 and 2 pi side by side,
// each with nodes of its own - and so do blocks meshed to meet node to node. Their sides there
// are no boundary of the body, but as separate nodes they are: two facets facing each other
// inside the wall, a slit that a particle pressed into the wall finds at distance 0 (no force:
// a tube with its seam at the bottom pressed 4 % less than the analytic cylinder). Welded, the
// boundary facets (discretization/OrientedFacets) leave them out; the cells' volume and moments
// are unchanged (the two facets' contributions cancelled).
#pragma once

#include <string>
#include <vector>

#include "mesh/BackgroundMesh.hpp"

namespace efg {

/// A mesh of `blocks` only (the others left out, no node or side sets), its nodes those of the
/// blocks with nodes closer than `tolerance` x the blocks' extent welded into the first of them.
BackgroundMesh welded_blocks(const BackgroundMesh& mesh, const std::vector<std::string>& blocks,
                             double tolerance = 1e-9);

}  // namespace efg
