// Hand-computed values of the contact geometry and the curve integral the rigid bodies move by:
// signed distances and outward normals of the analytic shapes (contact/RigidShape.hpp), and the
// integral of a piecewise-linear curve (model/Curves: prescribed travel in implicit stages).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/RigidShape.hpp"
#include "model/Curves.hpp"

namespace {

using efg::contact::proximity;
using efg::contact::Shape;

TEST(RigidShape, TurnedBoxIsEvaluatedInItsOwnFrame) {
  // The box [-1, 1] x [-0.5, 0.5] turned by 90 degrees about its centre stands as
  // [-0.5, 0.5] x [-1, 1]: (0, 0.9) is 0.1 inside its top face, (0.7, 0) 0.2 right of it.
  Shape s;
  s.kind = Shape::Kind::box;
  s.dim = 2;
  s.lower[0] = -1.0;
  s.lower[1] = -0.5;
  s.upper[0] = 1.0;
  s.upper[1] = 0.5;
  const double u[3] = {0, 0, 0}, quarter = 2.0 * std::atan(1.0);
  const double inside[3] = {0, 0.9, 0}, right[3] = {0.7, 0, 0};
  const auto a = efg::contact::proximity_turned(s, inside, u, quarter);
  EXPECT_NEAR(a.gap, -0.1, 1e-14);
  EXPECT_NEAR(a.normal[0], 0.0, 1e-14);
  EXPECT_NEAR(a.normal[1], 1.0, 1e-14);
  const auto b = efg::contact::proximity_turned(s, right, u, quarter);
  EXPECT_NEAR(b.gap, 0.2, 1e-14);
  EXPECT_NEAR(b.normal[0], 1.0, 1e-14);
  EXPECT_NEAR(b.normal[1], 0.0, 1e-14);
  // unturned, (0, 0.9) is outside the box by 0.4
  EXPECT_NEAR(efg::contact::proximity_turned(s, inside, u, 0.0).gap, 0.4, 1e-14);
}

TEST(RigidShape, PlaneGapAlongItsNormal) {
  Shape s;
  s.kind = Shape::Kind::plane;
  s.dim = 2;
  s.point[1] = 1.0;
  s.normal[0] = 0.6;  // unit (0.6, 0.8)
  s.normal[1] = 0.8;
  const double x[3] = {1.0, 0.0, 0.0}, u[3] = {0.0, 0.5, 0.0};
  // x - u - point = (1, -1.5): gap 0.6 - 1.2 = -0.6
  const auto p = proximity(s, x, u);
  EXPECT_NEAR(p.gap, -0.6, 1e-15);
  EXPECT_DOUBLE_EQ(p.normal[0], 0.6);
  EXPECT_DOUBLE_EQ(p.normal[1], 0.8);
}

TEST(RigidShape, SphereAndCylinderMeasureFromTheCenterOrAxis) {
  Shape s;
  s.kind = Shape::Kind::sphere;
  s.dim = 3;
  s.radius = 2.0;
  const double x[3] = {1.0, 2.0, 2.0}, u[3] = {0.0, 0.0, 0.0};
  const auto p = proximity(s, x, u);  // |x| = 3
  EXPECT_NEAR(p.gap, 1.0, 1e-15);
  EXPECT_NEAR(p.normal[2], 2.0 / 3.0, 1e-15);
  s.kind = Shape::Kind::cylinder;  // axis z: distance sqrt(1 + 4)
  const auto c = proximity(s, x, u);
  EXPECT_NEAR(c.gap, std::sqrt(5.0) - 2.0, 1e-15);
  EXPECT_NEAR(c.normal[1], 2.0 / std::sqrt(5.0), 1e-15);
  EXPECT_EQ(c.normal[2], 0.0);
}

TEST(RigidShape, BoxInsideTakesTheNearestFaceOutsideTheNearestPoint) {
  Shape s;
  s.kind = Shape::Kind::box;
  s.dim = 2;
  s.lower[0] = 0;
  s.lower[1] = 0;
  s.upper[0] = 4;
  s.upper[1] = 1;
  const double zero[3] = {0, 0, 0};
  const double inside[3] = {3.5, 0.9, 0};  // 0.1 below the top, 0.5 from the right
  const auto p = proximity(s, inside, zero);
  EXPECT_NEAR(p.gap, -0.1, 1e-15);
  EXPECT_EQ(p.normal[1], 1.0);
  const double corner[3] = {7.0, 5.0, 0};  // 3, 4 from the corner (4, 1)
  const auto q = proximity(s, corner, zero);
  EXPECT_NEAR(q.gap, 5.0, 1e-15);
  EXPECT_NEAR(q.normal[0], 0.6, 1e-15);
}

TEST(Curves, IntegralOfAPiecewiseLinearCurve) {
  efg::CurveSpec c{"c", {0.0, 1.0, 3.0}, {0.0, 2.0, 2.0}};
  EXPECT_NEAR(efg::curve_integral(c, 0.0, 3.0), 1.0 + 4.0, 1e-15);
  EXPECT_NEAR(efg::curve_integral(c, 0.5, 2.0), 0.75 + 2.0, 1e-15);
  EXPECT_NEAR(efg::curve_integral(c, 3.0, 4.0), 2.0, 1e-15);  // constant beyond the end
  EXPECT_NEAR(efg::curve_integral(c, 2.0, 0.5), -2.75, 1e-15);
}

}  // namespace
