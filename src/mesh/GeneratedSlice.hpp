// One rank's slice (mesh/MeshSlice.hpp) of a built-in mesh, made without making the rest: the
// nodes [n r / p, n (r + 1) / p), the same range of the cells and of every set's entries, each
// equal to that range of the mesh generate_mesh and append_generated make whole (the same
// numbering, coordinates, perturbation, cells, names and ids). parallel/LocalMesh.hpp turns the
// slices into each rank's part, as for a mesh file read in slices (mesh.read: distributed), so
// no rank ever holds the whole generated mesh (issue 20, item 3).
#pragma once

#include <vector>

#include "mesh/MeshGenerator.hpp"
#include "mesh/MeshSlice.hpp"

namespace efg {

/// Rank `rank` of `size`'s slice of the mesh generated from `main` with the separate bodies
/// `more` appended (append_generated's order). Throws InputError on an invalid spec.
MeshSlice generate_slice(const GeneratorSpec& main, const std::vector<GeneratorSpec>& more,
                         int rank, int size);

}  // namespace efg
