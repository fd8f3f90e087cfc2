// Reads one rank's slice of an Exodus mesh (mesh/MeshSlice.hpp): its range of the nodes, of the
// cells and of every set's entries, through Exodus' partial reads, so that no rank reads or holds
// the whole mesh. Every rank opens the file itself (read-only; a parallel file system serves
// them side by side).
#pragma once

#include <string>

#include "mesh/MeshSlice.hpp"

namespace efg {

/// Rank `rank` of `size`'s slice. Throws InputError (the same messages as read_exodus_mesh) on
/// anything unreadable or unsupported; names of unnamed entities as read_exodus_mesh gives them.
MeshSlice read_exodus_slice(const std::string& path, int rank, int size);

}  // namespace efg
