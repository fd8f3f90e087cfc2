// The UMFPACK factorization (solvers/SparseLU): solutions of systems whose answer is known by
// hand, rows handed over in any column order, refactoring with the same pattern, and a singular
// matrix reported.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "solvers/SparseLU.hpp"

namespace efg {
namespace {

TEST(SparseLU, SolvesANonsymmetricSystemGivenWithUnsortedColumns) {
  // A = [[4, -1, 0, 2], [1, 5, -2, 0], [0, 3, 6, -1], [-2, 0, 1, 7]], x = (1, 2, 3, 4):
  // b = A x = (4 - 2 + 8, 1 + 10 - 6, 6 + 18 - 4, -2 + 3 + 28) = (10, 5, 20, 29) by hand.
  const std::vector<std::int64_t> start{0, 3, 6, 9, 12};
  const std::vector<std::int64_t> column{3, 0, 1, 2, 1, 0, 3, 1, 2, 2, 0, 3};
  const std::vector<double> value{2, 4, -1, -2, 5, 1, -1, 3, 6, 1, -2, 7};
  SparseLU lu;
  lu.factor(4, start, column, value);
  const double b[4] = {10, 5, 20, 29};
  double x[4];
  lu.solve(b, x);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x[i], i + 1.0, 1e-14) << i;
  // Same pattern, new values (the symbolic analysis is reused): A' = 2 A, so x' = x / 2.
  std::vector<double> doubled(value);
  for (auto& v : doubled) v *= 2;
  lu.factor(4, start, column, doubled);
  lu.solve(b, x);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x[i], (i + 1.0) / 2, 1e-14) << i;
}

TEST(SparseLU, ReproducesTheQuadraticOfTheDiscreteLaplacian) {
  // -u'' = 2 on (0, 1), u(0) = u(1) = 0: u = x (1 - x). The three-point difference is exact for
  // a quadratic, so the discrete solution equals it at the nodes (to round-off).
  const int n = 2000;
  const double h = 1.0 / (n + 1);
  std::vector<std::int64_t> start{0}, column;
  std::vector<double> value;
  for (int i = 0; i < n; ++i) {
    for (int j : {i - 1, i, i + 1})
      if (j >= 0 && j < n) {
        column.push_back(j);
        value.push_back(j == i ? 2 / (h * h) : -1 / (h * h));
      }
    start.push_back(static_cast<std::int64_t>(column.size()));
  }
  SparseLU lu;
  lu.factor(n, start, column, value);
  EXPECT_GE(lu.factor_nonzeros(), 2 * n);
  std::vector<double> b(n, 2.0), u(n);
  lu.solve(b.data(), u.data());
  double worst = 0;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 1) * h;
    worst = std::max(worst, std::abs(u[i] - x * (1 - x)));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(SparseLU, ReportsASingularMatrix) {
  // Row 2 = row 0 + row 1.
  const std::vector<std::int64_t> start{0, 2, 4, 7};
  const std::vector<std::int64_t> column{0, 1, 1, 2, 0, 1, 2};
  const std::vector<double> value{1, 2, 3, 4, 1, 5, 4};
  SparseLU lu;
  try {
    lu.factor(3, start, column, value);
    FAIL() << "a singular matrix was factored";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace efg
