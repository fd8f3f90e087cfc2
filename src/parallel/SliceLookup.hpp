// Values held in slices, fetched by global index: rank r holds the `width` values of every item
// in [n r / p, n (r + 1) / p) (a slice of a file, mesh/MeshSlice.hpp), and each rank asks for
// the items it needs (a restart record's values at the nodes of its part). One all-to-all of the
// indices asked, one of the values answered; nothing the size of the whole is allocated.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/Comm.hpp"

namespace efg {

/// The values of items `wanted` (global indices in [0, count), ascending), `width` each, from
/// the slices `held` (this rank's slice of `count` items, `width` values each). Collective.
std::vector<double> fetch_from_slices(const CommPtr& comm, GlobalIndex count, std::size_t width,
                                      const std::vector<double>& held,
                                      const std::vector<GlobalIndex>& wanted);

}  // namespace efg
