// The MUMPS factorization (solvers/DistributedLU) on 1, 2 and 3 ranks: entries handed over by
// whichever rank holds them (a row split over ranks, duplicates summed), solutions known by hand,
// refactoring with the same pattern, a singular matrix reported, and a well-conditioned matrix at
// a tiny scale not mistaken for a singular one.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/DistributedLU.hpp"

namespace efg {
namespace {

int rank_of(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}
int size_of(MPI_Comm comm) {
  int s = 0;
  MPI_Comm_size(comm, &s);
  return s;
}

// The entries of A = [[4, -1, 0, 2], [1, 5, -2, 0], [0, 3, 6, -1], [-2, 0, 1, 7]] (times
// `scale`), dealt round-robin over the ranks, with A(0, 0) = 4 given as 1 + 3 on two ranks.
struct Entries {
  std::vector<int> rows, columns;
  std::vector<double> values;
};
Entries dealt(MPI_Comm comm, double scale) {
  const int rows[] = {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
  const int columns[] = {0, 0, 1, 3, 0, 1, 2, 1, 2, 3, 0, 2, 3};
  const double values[] = {1, 3, -1, 2, 1, 5, -2, 3, 6, -1, -2, 1, 7};
  Entries e;
  for (int k = 0; k < 13; ++k)
    if (k % size_of(comm) == rank_of(comm)) {
      e.rows.push_back(rows[k]);
      e.columns.push_back(columns[k]);
      e.values.push_back(scale * values[k]);
    }
  return e;
}

TEST(DistributedLU, SolvesANonsymmetricSystemDealtOverTheRanks) {
  // x = (1, 2, 3, 4): b = A x = (10, 5, 20, 29) by hand.
  DistributedLU lu(MPI_COMM_WORLD);
  auto e = dealt(MPI_COMM_WORLD, 1.0);
  lu.factor(4, e.rows, e.columns, e.values);
  const bool root = rank_of(MPI_COMM_WORLD) == 0;
  std::vector<double> b{10, 5, 20, 29};
  lu.solve(root ? b.data() : nullptr, 1);
  if (root) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(b[i], i + 1.0, 1e-14) << i;
  }
  // Same pattern, values doubled (the analysis is kept): x' = x / 2; two right-hand sides.
  e = dealt(MPI_COMM_WORLD, 2.0);
  lu.factor(4, e.rows, e.columns, e.values);
  std::vector<double> two{10, 5, 20, 29, 20, 10, 40, 58};
  lu.solve(root ? two.data() : nullptr, 2);
  if (root)
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(two[i], (i + 1.0) / 2, 1e-14) << i;
      EXPECT_NEAR(two[4 + i], i + 1.0, 1e-14) << i;
    }
  EXPECT_GE(lu.factor_nonzeros(), 12);
}

TEST(DistributedLU, ATinyScaleIsNotASingularMatrix) {
  // 1e-30 A is as well conditioned as A: the null-pivot test is relative to the matrix's norm.
  DistributedLU lu(MPI_COMM_WORLD);
  const auto e = dealt(MPI_COMM_WORLD, 1e-30);
  lu.factor(4, e.rows, e.columns, e.values);
  std::vector<double> b{10e-30, 5e-30, 20e-30, 29e-30};
  const bool root = rank_of(MPI_COMM_WORLD) == 0;
  lu.solve(root ? b.data() : nullptr, 1);
  if (root) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(b[i], i + 1.0, 1e-13) << i;
  }
}

TEST(DistributedLU, ReportsASingularMatrixOnEveryRank) {
  // Row 2 = row 0 + row 1 (exactly, and with 1e-15 relative in its last entry: singular to
  // round-off, which the default MUMPS threshold, about 1e-21 of the norm, would miss).
  for (const double tiny : {0.0, 1e-15}) {
    const int rows[] = {0, 0, 1, 1, 2, 2, 2};
    const int columns[] = {0, 1, 1, 2, 0, 1, 2};
    const double values[] = {1, 2, 3, 4, 1, 5, 4 * (1 + tiny)};
    std::vector<int> r, c;
    std::vector<double> v;
    for (int k = 0; k < 7; ++k)
      if (k % size_of(MPI_COMM_WORLD) == rank_of(MPI_COMM_WORLD)) {
        r.push_back(rows[k]);
        c.push_back(columns[k]);
        v.push_back(values[k]);
      }
    DistributedLU lu(MPI_COMM_WORLD);
    try {
      lu.factor(3, r, c, v);
      ADD_FAILURE() << "a singular matrix was factored (perturbation " << tiny << ")";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
    }
  }
}

TEST(DistributedLU, SolvesALargeGridSystemDealtInBlocks) {
  // A nonsymmetric convection-diffusion stencil on a 240 x 240 grid (57,600 unknowns, fronts
  // large enough to be shared by the processes), rows dealt in blocks over the ranks;
  // x_i = 1 + (i mod 7) known, b = A x formed here.
  const int k = 240, n = k * k;
  const int ranks = size_of(MPI_COMM_WORLD), me = rank_of(MPI_COMM_WORLD);
  auto x_of = [](int i) { return 1.0 + (i % 7); };
  std::vector<int> rows, columns;
  std::vector<double> values;
  std::vector<double> b(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    const int gx = i % k, gy = i / k;
    auto add = [&](int j, double v) {
      b[static_cast<std::size_t>(i)] += v * x_of(j);
      if (static_cast<long long>(i) * ranks / n != me) return;
      rows.push_back(i);
      columns.push_back(j);
      values.push_back(v);
    };
    add(i, 4.5);
    if (gx > 0) add(i - 1, -1.3);
    if (gx + 1 < k) add(i + 1, -0.7);
    if (gy > 0) add(i - k, -1.1);
    if (gy + 1 < k) add(i + k, -0.9);
  }
  DistributedLU lu(MPI_COMM_WORLD);
  lu.factor(n, rows, columns, values);
  lu.solve(me == 0 ? b.data() : nullptr, 1);
  if (me == 0) {
    double worst = 0;
    for (int i = 0; i < n; ++i)
      worst = std::max(worst, std::abs(b[static_cast<std::size_t>(i)] - x_of(i)));
    EXPECT_LT(worst, 1e-10);
  }
}

}  // namespace
}  // namespace efg
