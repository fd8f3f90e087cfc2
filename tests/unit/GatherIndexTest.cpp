// The transpose behind every gather kernel: each column lists exactly the entries that name it,
// in ascending order, and the row of every entry is right.
#include <gtest/gtest.h>

#include <random>

#include "discretization/GatherIndex.hpp"

namespace efg {
namespace {

TEST(GatherIndex, TransposesARandomTable) {
  std::mt19937_64 rng(3);
  const std::size_t rows = 500, columns = 120;
  std::vector<std::size_t> offsets{0};
  std::vector<int> column;
  for (std::size_t r = 0; r < rows; ++r) {
    const auto n = rng() % 40;  // some rows empty
    for (std::size_t k = 0; k < n; ++k)
      column.push_back(static_cast<int>(rng() % (columns - 1)));  // last column empty
    offsets.push_back(column.size());
  }
  const auto g = gather_index(to_device(offsets, "offsets"), to_device(column, "column"), columns);
  const auto col_offsets = to_host(g.offsets);
  const auto entry = to_host(g.entry);
  const auto row = to_host(g.row_of_entry);
  ASSERT_EQ(col_offsets.size(), columns + 1);
  ASSERT_EQ(col_offsets.back(), column.size());
  for (std::size_t c = 0; c < columns; ++c) {
    std::vector<std::size_t> expected;
    for (std::size_t k = 0; k < column.size(); ++k)
      if (static_cast<std::size_t>(column[k]) == c) expected.push_back(k);
    const std::vector<std::size_t> found(
        entry.begin() + static_cast<std::ptrdiff_t>(col_offsets[c]),
        entry.begin() + static_cast<std::ptrdiff_t>(col_offsets[c + 1]));
    EXPECT_EQ(found, expected) << "column " << c;
  }
  for (std::size_t r = 0; r < rows; ++r)
    for (auto k = offsets[r]; k < offsets[r + 1]; ++k) EXPECT_EQ(row[k], static_cast<int>(r));
}

}  // namespace
}  // namespace efg
