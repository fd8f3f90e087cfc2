// The transpose of a compressed-row table: for every column (particle), the table entries that
// reference it, in ascending entry order. Kernels that add point contributions to particles use
// it to *gather* (one work item per particle sums its own entries) instead of scattering with
// atomics: no two work items write the same particle, and every sum runs in the same order on
// any number of threads, so results do not depend on the thread count (docs/threads.md).
#pragma once

#include "core/DeviceArrays.hpp"

namespace efg {

struct GatherIndex {
  DeviceView<std::size_t*> offsets;  ///< columns + 1
  /// entry k of the table, ascending within a column (32 bits: half the memory of a size_t per
  /// entry, issue 20; a table of more than 2^31 - 1 entries on one rank is refused)
  DeviceView<int*> entry;
  DeviceView<int*> row_of_entry;  ///< the row of every entry of the table
};

/// Transposes the table (row offsets, column of every entry; columns in [0, column_count)).
/// Counting and filling run as Kokkos kernels (integer atomics for the counts and slots), then
/// every column's entries are sorted, so the result is the same on any execution space.
GatherIndex gather_index(const DeviceView<const std::size_t*>& row_offsets,
                         const DeviceView<const int*>& column, std::size_t column_count);

}  // namespace efg
