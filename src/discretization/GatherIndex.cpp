#include "discretization/GatherIndex.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace efg {

GatherIndex gather_index(const DeviceView<const std::size_t*>& row_offsets,
                         const DeviceView<const int*>& column, std::size_t column_count) {
  GatherIndex g;
  const auto entries = column.extent(0);
  const auto rows = row_offsets.extent(0) > 0 ? row_offsets.extent(0) - 1 : 0;
  if (entries > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("a table of " + std::to_string(entries) +
                            " entries on one rank: more than 32-bit indices address; run on "
                            "more ranks");
  g.offsets = DeviceView<std::size_t*>("efg::gather offsets", column_count + 1);
  g.entry = DeviceView<int*>(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::gather entry"),
                             entries);
  g.row_of_entry = DeviceView<int*>(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::gather rows"), entries);
  const auto offsets = g.offsets;
  const auto entry = g.entry;
  const auto row_of_entry = g.row_of_entry;
  using Range = Kokkos::RangePolicy<ExecSpace>;

  Kokkos::parallel_for(
      "efg::gather_rows", Range(0, rows), KOKKOS_LAMBDA(const std::size_t r) {
        for (auto k = row_offsets(r); k < row_offsets(r + 1); ++k)
          row_of_entry(k) = static_cast<int>(r);
      });
  // Counts per column, shifted by one so that an exclusive scan turns them into offsets.
  Kokkos::parallel_for(
      "efg::gather_count", Range(0, entries), KOKKOS_LAMBDA(const std::size_t k) {
        Kokkos::atomic_increment(&offsets(static_cast<std::size_t>(column(k)) + 1));
      });
  Kokkos::parallel_scan(
      "efg::gather_scan", Range(0, column_count + 1),
      KOKKOS_LAMBDA(const std::size_t c, std::size_t& running, const bool final) {
        running += offsets(c);
        if (final) offsets(c) = running;
      });
  DeviceView<std::size_t*> fill("efg::gather fill", column_count);
  Kokkos::parallel_for(
      "efg::gather_fill", Range(0, entries), KOKKOS_LAMBDA(const std::size_t k) {
        const auto c = static_cast<std::size_t>(column(k));
        entry(offsets(c) + Kokkos::atomic_fetch_add(&fill(c), std::size_t(1))) =
            static_cast<int>(k);
      });
  // The slots above were taken in whatever order the threads ran: sort each column (short lists).
  Kokkos::parallel_for(
      "efg::gather_sort", Range(0, column_count), KOKKOS_LAMBDA(const std::size_t c) {
        for (auto i = offsets(c) + 1; i < offsets(c + 1); ++i) {
          const auto value = entry(i);
          auto j = i;
          for (; j > offsets(c) && entry(j - 1) > value; --j) entry(j) = entry(j - 1);
          entry(j) = value;
        }
      });
  return g;
}

}  // namespace efg
