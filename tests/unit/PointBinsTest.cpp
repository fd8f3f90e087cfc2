#include <gtest/gtest.h>

#include <random>
#include <set>

#include "geometry/PointBins.hpp"
#include "mesh/MeshGenerator.hpp"
#include "parallel/NodePartition.hpp"

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

// The ghost layer against brute force: the nodes of the other ranks within the radius of a node
// of this one (the mesh cut at x = 0.5 between ranks 0 and 1, and a third rank owning none).
TEST(GhostLayer, ForeignNodesNearOwnedOnesByBruteForce) {
  GeneratorSpec spec;
  spec.dimension = 3;
  spec.element = CellType::hex8;
  spec.cells = {11, 6, 5};
  spec.upper = {1, 1, 1};
  spec.perturbation = 0.3;
  const auto mesh = generate_mesh(spec);
  const auto n = mesh.node_count();
  std::vector<int> owner(n);
  for (std::size_t i = 0; i < n; ++i) owner[i] = mesh.coordinates[3 * i] < 0.5 ? 0 : 1;
  for (double radius : {0.0, 0.1, 0.23, 0.6})
    for (int rank : {0, 1, 2}) {
      std::vector<LocalIndex> expected;
      for (std::size_t j = 0; j < n; ++j) {
        if (owner[j] == rank) continue;
        bool near = false;
        for (std::size_t i = 0; i < n && !near; ++i) {
          if (owner[i] != rank) continue;
          double d2 = 0;
          for (std::size_t d = 0; d < 3; ++d) {
            const double dx = mesh.coordinates[3 * i + d] - mesh.coordinates[3 * j + d];
            d2 += dx * dx;
          }
          near = radius > 0 && d2 <= radius * radius;
        }
        if (near) expected.push_back(static_cast<LocalIndex>(j));
      }
      EXPECT_EQ(ghost_layer(mesh, owner, rank, radius), expected)
          << "radius " << radius << " rank " << rank;
      if (rank == 0 && radius == 0.23) {
        EXPECT_GT(expected.size(), 0u);
      }
    }
}

}  // namespace
}  // namespace efg
