#include <gtest/gtest.h>

#include <vector>

#include "core/DeviceArrays.hpp"

namespace efg {
namespace {

// The kernels' view of a host table: the host array itself where the kernels read host memory
// (Serial, OpenMP: no second copy, issue 20), else a copy; either way the same values in the same
// row-major places.
TEST(DeviceViewOf, IsTheHostTableItselfWhereKernelsReadHostMemory) {
  const std::vector<double> table = {1, 2, 3, 4, 5, 6};  // 3 rows of 2
  const std::vector<std::size_t> offsets = {0, 2, 6};
  const auto matrix = device_view_of(table, 3, 2, "test matrix");
  const auto vector = device_view_of(offsets, "test offsets");
  ASSERT_EQ(matrix.extent(0), 3u);
  ASSERT_EQ(matrix.extent(1), 2u);
  ASSERT_EQ(vector.extent(0), 3u);
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible) {
    EXPECT_EQ(matrix.data(), table.data());
    EXPECT_EQ(vector.data(), offsets.data());
  }
  EXPECT_EQ(to_host(matrix), table);
  EXPECT_EQ(to_host(vector), offsets);
}

}  // namespace
}  // namespace efg
