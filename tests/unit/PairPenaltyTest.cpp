// The implicit penalty pair between deformable parts (contact/PairPenalty.hpp): its force by hand
// for a particle pressed into a segment, equal and opposite forces on the particle and the facet
// (momentum), and its derivatives by forward AD (the tangent of ImplicitSurfaceContact) against
// central differences of the same function, in 2D and 3D, with every point moving.
#include <gtest/gtest.h>

#include <Sacado.hpp>

#include <cmath>

#include "contact/PairPenalty.hpp"

namespace {

using efg::contact::pair_penalty_forces;
using Fad = Sacado::Fad::SFad<double, 12>;

TEST(PairPenalty, ForceByHandAndBalance) {
  // Segment (2, 0) -> (0, 0), outward normal (0, 1); the particle at (0.5, -0.25): gap -0.25,
  // weights (0.25, 0.75). k = 4: F = 4 x 0.25 x (0, 1) = (0, 1) on the particle, -w_a F on the
  // segment's nodes.
  const double node[3][3] = {{2, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  const double x[3] = {0.5, -0.25, 0};
  double f[4][3];
  pair_penalty_forces(x, node, 2, 4.0, f);
  EXPECT_DOUBLE_EQ(f[0][0], 0.0);
  EXPECT_DOUBLE_EQ(f[0][1], 1.0);
  EXPECT_DOUBLE_EQ(f[1][1], -0.25);
  EXPECT_DOUBLE_EQ(f[2][1], -0.75);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[0][i] + f[1][i] + f[2][i], 0.0, 1e-15);
}

// dF_P,i / dx_Q,j by AD against (F(x + h e) - F(x - h e)) / 2h for every point Q and direction
// j: the largest difference relative to the largest derivative.
double tangent_error(int dim) {
  double p[4][3] = {{0.3, -0.02, 0.1}, {0.0, 0.01, -0.05}, {1.0, -0.03, 0.02}, {0.2, 0.04, 0.9}};
  if (dim == 2)
    for (auto& q : p) q[2] = 0.0;
  const int points = 1 + dim;
  const double k = 7.0;
  Fad x[3], c[3][3], f[4][3];
  for (int i = 0; i < 3; ++i) {
    x[i] = p[0][i];
    if (i < dim) x[i].diff(i, 12);
    for (int a = 0; a < dim; ++a) {
      c[a][i] = p[1 + a][i];
      if (i < dim) c[a][i].diff((a + 1) * dim + i, 12);
    }
  }
  pair_penalty_forces(x, c, dim, k, f);
  double worst = 0, largest = 0;
  const double h = 1e-6;
  for (int q = 0; q < points; ++q)
    for (int j = 0; j < dim; ++j) {
      double plus[4][3], minus[4][3];
      for (int s = -1; s <= 1; s += 2) {
        double moved[4][3];
        for (int a = 0; a < 4; ++a)
          for (int i = 0; i < 3; ++i) moved[a][i] = p[a][i];
        moved[q][j] += s * h;
        const double corner[3][3] = {{moved[1][0], moved[1][1], moved[1][2]},
                                     {moved[2][0], moved[2][1], moved[2][2]},
                                     {moved[3][0], moved[3][1], moved[3][2]}};
        pair_penalty_forces(moved[0], corner, dim, k, s > 0 ? plus : minus);
      }
      for (int P = 0; P < points; ++P)
        for (int i = 0; i < dim; ++i) {
          const double fd = (plus[P][i] - minus[P][i]) / (2 * h);
          const double ad = f[P][i].dx(q * dim + j);
          worst = std::fmax(worst, std::abs(fd - ad));
          largest = std::fmax(largest, std::abs(ad));
        }
    }
  return worst / largest;
}

TEST(PairPenalty, TangentByADEqualsCentralDifferences2D) {
  EXPECT_LT(tangent_error(2), 1e-8);
}

TEST(PairPenalty, TangentByADEqualsCentralDifferences3D) {
  EXPECT_LT(tangent_error(3), 1e-8);
}

}  // namespace
