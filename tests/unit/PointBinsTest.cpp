#include <gtest/gtest.h>

#include <random>
#include <set>

#include "geometry/PointBins.hpp"

namespace efg {
namespace {

TEST(PointBins, FindsExactlyThePointsWithinRadius) {
  for (int dim : {2, 3}) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 3.0);
    const std::size_t n = 2000;
    std::vector<double> x(n * static_cast<std::size_t>(dim));
    for (auto& v : x) v = u(rng);
    for (double bin : {0.05, 0.3, 2.0}) {
      const PointBins bins(x.data(), n, dim, bin);
      for (std::size_t q = 0; q < 50; ++q) {
        const double* p = x.data() + q * static_cast<std::size_t>(dim);
        const double radius = 0.1 + 0.01 * static_cast<double>(q);
        std::set<std::size_t> found, expected;
        bins.for_each_within(p, radius,
                             [&](std::size_t j) { EXPECT_TRUE(found.insert(j).second); });
        for (std::size_t j = 0; j < n; ++j) {
          double d2 = 0;
          for (int d = 0; d < dim; ++d) {
            const double dx =
                x[j * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)] - p[d];
            d2 += dx * dx;
          }
          if (d2 <= radius * radius) expected.insert(j);
        }
        EXPECT_EQ(found, expected) << "dim " << dim << " bin " << bin << " query " << q;
        // Away from the cloud too: the query point shifted by up to 3 along the first axis.
        double away[3] = {p[0], p[1], dim == 3 ? p[2] : 0.0};
        away[0] += 0.1 * static_cast<double>(q % 31);
        bool near = false;
        for (std::size_t j = 0; j < n && !near; ++j) {
          double d2 = 0;
          for (int d = 0; d < dim; ++d) {
            const double dx =
                x[j * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)] - away[d];
            d2 += dx * dx;
          }
          near = d2 <= radius * radius;
        }
        EXPECT_EQ(bins.any_within(away, radius), near) << "dim " << dim << " query " << q;
      }
    }
  }
}

}  // namespace
}  // namespace efg
