// Hand-computed values of the geometry of contact between deformable parts: the projection of
// a particle on a segment and a triangle (gap, outward normal, facet weights; the clipping
// that keeps the weights summing to one) and the bins that list the facets near a point
// (contact/FacetProjection.hpp, contact/FacetBins).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/FacetBins.hpp"
#include "contact/FacetProjection.hpp"

namespace {

using efg::contact::FacetBins;
using efg::contact::project_on_facet;

TEST(FacetProjection, SegmentGapNormalAndWeights) {
  // Segment from (2, 0) to (0, 0): its outward normal (dy, -dx) / L = (0, 1).
  const double node[3][3] = {{2, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  const double x[3] = {0.5, -0.25, 0};
  const auto p = project_on_facet(x, node, 2, 1e-6);
  EXPECT_TRUE(p.over);
  EXPECT_DOUBLE_EQ(p.gap, -0.25);
  EXPECT_DOUBLE_EQ(p.normal[0], 0.0);
  EXPECT_DOUBLE_EQ(p.normal[1], 1.0);
  EXPECT_DOUBLE_EQ(p.weight[0], 0.25);  // 0.5 from the second node: 1 - 1.5 / 2
  EXPECT_DOUBLE_EQ(p.weight[1], 0.75);
}

TEST(FacetProjection, ObliqueSegment) {
  // Segment from (0, 0) to (1, 1): outward normal (dy, -dx) / L = (1, -1) / sqrt 2; the point
  // (1, 0) lies 1 / sqrt 2 outside, over the segment's middle.
  const double node[3][3] = {{0, 0, 0}, {1, 1, 0}, {0, 0, 0}};
  const double x[3] = {1, 0, 0};
  const auto p = project_on_facet(x, node, 2, 1e-6);
  const double r = 1.0 / std::sqrt(2.0);
  EXPECT_TRUE(p.over);
  EXPECT_NEAR(p.gap, r, 1e-15);
  EXPECT_NEAR(p.normal[0], r, 1e-15);
  EXPECT_NEAR(p.normal[1], -r, 1e-15);
  EXPECT_NEAR(p.weight[0], 0.5, 1e-15);
  EXPECT_NEAR(p.weight[1], 0.5, 1e-15);
}

TEST(FacetProjection, BeyondTheEndIsNotOverAndWeightsStayOnTheFacet) {
  const double node[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};  // normal (0, -1)
  const double x[3] = {1.5, -0.1, 0};
  const auto p = project_on_facet(x, node, 2, 1e-6);
  EXPECT_FALSE(p.over);
  EXPECT_DOUBLE_EQ(p.gap, 0.1);
  EXPECT_DOUBLE_EQ(p.weight[0], 0.0);
  EXPECT_DOUBLE_EQ(p.weight[1], 1.0);
  // within the tolerance (in facet coordinates) it still counts
  const double near_end[3] = {1.005, 0.2, 0};
  EXPECT_TRUE(project_on_facet(near_end, node, 2, 0.01).over);
}

TEST(FacetProjection, TriangleBarycentricWeights) {
  // Triangle (0,0,1), (2,0,1), (0,2,1): normal (0, 0, 1); the point over (0.5, 0.5) has
  // barycentric weights (1 - 0.25 - 0.25, 0.25, 0.25).
  const double node[3][3] = {{0, 0, 1}, {2, 0, 1}, {0, 2, 1}};
  const double x[3] = {0.5, 0.5, 0.7};
  const auto p = project_on_facet(x, node, 3, 1e-6);
  EXPECT_TRUE(p.over);
  EXPECT_NEAR(p.gap, -0.3, 1e-15);
  EXPECT_DOUBLE_EQ(p.normal[2], 1.0);
  EXPECT_DOUBLE_EQ(p.weight[0], 0.5);
  EXPECT_DOUBLE_EQ(p.weight[1], 0.25);
  EXPECT_DOUBLE_EQ(p.weight[2], 0.25);
  // outside the edge x + y = 2: not over
  const double out[3] = {1.5, 1.0, 0.9};
  EXPECT_FALSE(project_on_facet(out, node, 3, 1e-6).over);
}

TEST(FacetBins, ListsTheFacetsWhoseBoxesHoldThePoint) {
  // Three 2D boxes: [0,1]x[0,1], [2,3]x[0,1], [0,3]x[5,6].
  const std::vector<double> lower = {0, 0, 2, 0, 0, 5}, upper = {1, 1, 3, 1, 3, 6};
  FacetBins bins;
  bins.build(2, lower, upper, 1.0);
  auto listed = [&](double x, double y) {
    const double p[3] = {x, y, 0};
    const auto [b, e] = bins.near(p);
    std::vector<int> out(b, e);
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_EQ(listed(0.5, 0.5), std::vector<int>({0}));
  EXPECT_EQ(listed(2.5, 0.5), std::vector<int>({1}));
  EXPECT_EQ(listed(1.5, 5.5), std::vector<int>({2}));
  EXPECT_TRUE(listed(1.5, 3.0).empty());
  EXPECT_TRUE(listed(-1.0, 0.5).empty());  // outside the grid
}

TEST(FacetBins, WidensItsBinsWhenThePartsAreFarApart) {
  // Two small boxes 1e6 apart with a bin size of 1: the grid keeps at most 8 per facet + 64
  // bins, and still finds both.
  const std::vector<double> lower = {0, 0, 1e6, 0}, upper = {1, 1, 1e6 + 1, 1};
  FacetBins bins;
  bins.build(2, lower, upper, 1.0);
  EXPECT_LE(bins.bin_count(), 8u * 2u + 64u);
  const double a[3] = {0.5, 0.5, 0}, b[3] = {1e6 + 0.5, 0.5, 0};
  const auto [a0, a1] = bins.near(a);
  const auto [b0, b1] = bins.near(b);
  EXPECT_TRUE(std::find(a0, a1, 0) != a1);
  EXPECT_TRUE(std::find(b0, b1, 1) != b1);
}

}  // namespace
