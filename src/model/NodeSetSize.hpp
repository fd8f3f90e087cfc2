// The size of a node set over the whole mesh when each rank holds part of it (a mesh read in
// slices, parallel/LocalMesh.hpp): its entries on owned nodes, summed over the ranks.
#pragma once

#include <cstddef>

#include "model/Model.hpp"

namespace efg {

/// Entries of `set` (a set of model.mesh) on nodes owned here, summed over the ranks
/// (collective). On a whole mesh, the set's size.
std::size_t owned_entries_over_ranks(const Model& model, const NodeSet& set);

}  // namespace efg
