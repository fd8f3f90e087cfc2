// Stabilized conforming nodal integration (Chen, Wu, Yoon, You 2001): divergence consistency
// and exact constant strains for linear fields, on perturbed node sets of every cell type.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <utility>

#include "discretization/IntegrationPoints.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "discretization/SmoothingFacets.hpp"
#include "support/Clouds.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

struct Setup {
  BackgroundMesh mesh;
  PartSpec part;
  ParticleCloud cloud;
  IntegrationPoints ip;
};

Setup make(CellType type, Integration scheme, double perturbation, int n = 4,
           SmoothingQuadrature quadrature = SmoothingQuadrature::split) {
  Setup s;
  s.mesh = generate_mesh(test::box_spec(type, n, perturbation, 17));
  s.part.name = "part";
  s.part.blocks = {"block_1"};
  s.part.section.integration = scheme;
  s.part.section.smoothing_quadrature = quadrature;
  s.part.section.dilation = {cell_dimension(type) == 3 ? 1.8 : 1.6};
  const std::vector<int> owner(s.mesh.node_count(), 0);
  s.cloud = make_particle_cloud(s.mesh, s.part, owner, 0, {});
  s.ip = integrate_part(s.mesh, s.part, s.cloud, owner, 0);
  return s;
}

class ByCell : public ::testing::TestWithParam<CellType> {};

// Largest |sum_L B~_I(x_L) V_L - integral over the boundary of phi_I n| over the particles I,
// relative to one particle's boundary flux (h^(dim-1)).
double divergence_error(const Setup& s) {
  const auto dim = static_cast<std::size_t>(s.mesh.dimension);
  // Left: sum_L B~_I(x_L) V_L for every particle I.
  std::vector<double> lhs(s.cloud.size() * dim, 0.0);
  for (std::size_t l = 0; l < s.ip.size(); ++l)
    for (auto k = s.ip.gradients.offsets[l]; k < s.ip.gradients.offsets[l + 1]; ++k)
      for (std::size_t d = 0; d < dim; ++d)
        lhs[static_cast<std::size_t>(s.ip.gradients.particles[k]) * dim + d] +=
            s.ip.gradients.values[k * dim + d] * s.ip.weight[l];
  // Right: the boundary integral of phi_I n over the part's boundary, same boundary quadrature.
  std::vector<SmoothingPoint> boundary;
  for (const auto& p : smoothing_points(s.mesh, s.part.blocks))
    if (p.minus < 0) boundary.push_back(p);
  std::vector<double> x;
  for (const auto& p : boundary)
    x.insert(x.end(), p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(dim));
  const auto phi = evaluate_shape_functions(s.cloud, x.data(), boundary.size(), false);
  std::vector<double> rhs(lhs.size(), 0.0), scale(s.cloud.size(), 0.0);
  for (std::size_t p = 0; p < boundary.size(); ++p)
    for (auto k = phi.neighbors.offsets[p]; k < phi.neighbors.offsets[p + 1]; ++k) {
      const auto i = static_cast<std::size_t>(phi.neighbors.particles[k]);
      for (std::size_t d = 0; d < dim; ++d) {
        rhs[i * dim + d] += phi.phi[k] * boundary[p].weighted_normal[d];
        scale[i] += std::abs(phi.phi[k] * boundary[p].weighted_normal[d]);
      }
    }
  // Relative to the size of one particle's boundary flux (h^(dim-1)).
  const double flux_scale = *std::max_element(scale.begin(), scale.end());
  if (!(flux_scale > 0.0)) return 1e300;
  double worst = 0;
  for (std::size_t i = 0; i < lhs.size(); ++i)
    worst = std::max(worst, std::abs(lhs[i] - rhs[i]) / flux_scale);
  return worst;
}

TEST_P(ByCell, DivergenceConsistency) {
  for (auto rule : {SmoothingQuadrature::split, SmoothingQuadrature::centroid})
    EXPECT_LT(divergence_error(make(GetParam(), Integration::scni, 0.3, 4, rule)), 1e-12)
        << cell_scene_name(GetParam()) << " rule " << static_cast<int>(rule);
}

// The rows are built for batches of 2048 particles (IntegrationPoints, build_scni): a part of
// 3,721 particles spans two, and its rows must still be divergence consistent.
TEST(SmoothedGradient, DivergenceConsistencyAcrossBatches) {
  const auto s = make(CellType::quad4, Integration::scni, 0.3, 60);
  ASSERT_GT(s.ip.size(), 2048u);
  EXPECT_LT(divergence_error(s), 1e-12);
}

TEST_P(ByCell, LinearFieldGivesExactConstantGradient) {
  const std::pair<Integration, SmoothingQuadrature> schemes[] = {
      {Integration::scni, SmoothingQuadrature::split},
      {Integration::scni, SmoothingQuadrature::centroid},
      {Integration::nodal, SmoothingQuadrature::split},
      {Integration::gauss, SmoothingQuadrature::split}};
  for (const auto& [scheme, rule] : schemes) {
    const auto s = make(GetParam(), scheme, 0.3, 4, rule);
    const auto dim = static_cast<std::size_t>(s.mesh.dimension);
    const double g[3][3] = {{0.3, -1.2, 0.7}, {2.0, 0.1, -0.4}, {-0.9, 0.5, 1.1}};
    const double a[3] = {0.2, -0.3, 0.05};
    double worst = 0;
    for (std::size_t l = 0; l < s.ip.size(); ++l) {
      double grad[3][3] = {};
      for (auto k = s.ip.gradients.offsets[l]; k < s.ip.gradients.offsets[l + 1]; ++k) {
        const auto* xi = s.cloud.x(static_cast<std::size_t>(s.ip.gradients.particles[k]));
        for (std::size_t i = 0; i < dim; ++i) {
          double u = a[i];
          for (std::size_t j = 0; j < dim; ++j) u += g[i][j] * xi[j];
          for (std::size_t d = 0; d < dim; ++d)
            grad[i][d] += u * s.ip.gradients.values[k * dim + d];
        }
      }
      for (std::size_t i = 0; i < dim; ++i)
        for (std::size_t j = 0; j < dim; ++j)
          worst = std::max(worst, std::abs(grad[i][j] - g[i][j]) / 2.0);
    }
    EXPECT_LT(worst, 1e-12) << cell_scene_name(GetParam()) << " scheme " << static_cast<int>(scheme)
                            << " rule " << static_cast<int>(rule);
  }
}

TEST_P(ByCell, WeightsAddUpToTheDomainVolume) {
  for (auto scheme : {Integration::scni, Integration::nodal, Integration::gauss}) {
    const auto s = make(GetParam(), scheme, 0.3);
    const double total = std::accumulate(s.ip.weight.begin(), s.ip.weight.end(), 0.0);
    EXPECT_NEAR(total, 2.0, 1e-12) << cell_scene_name(GetParam());
    for (double w : s.ip.weight) EXPECT_GT(w, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(AllCells, ByCell,
                         ::testing::Values(CellType::quad4, CellType::tri3, CellType::hex8,
                                           CellType::tet4, CellType::wedge6),
                         [](const auto& p) { return cell_scene_name(p.param); });

TEST(SmoothedGradient, NodalDomainsOfARegularGridAreItsDualCells) {
  const auto s = make(CellType::quad4, Integration::scni, 0.0, 2);  // h = 0.5
  for (std::size_t l = 0; l < s.ip.size(); ++l) {
    const auto* x = s.cloud.x(l);
    const bool edge_x = x[0] == 0.0 || x[0] == 2.0, edge_y = x[1] == 0.0 || x[1] == 1.0;
    EXPECT_NEAR(s.ip.weight[l], 0.25 * (edge_x ? 0.5 : 1.0) * (edge_y ? 0.5 : 1.0), 1e-15);
  }
}

// The facet quadrature itself (issue 13, item 10): 2 Gauss points per half segment integrate a
// quadratic along each facet exactly. On a regular grid of spacing h an interior node's domain is
// the dual cell [x - h/2, x + h/2] x [y - h/2, y + h/2], so for f = x y^2 the divergence theorem
// gives by hand: boundary integral of f n_x = integral of y^2 over the cell = h (y^2 h + h^3/12).
// Points moved to +-1/4 of the half segment integrate y^2 wrongly and fail this.
TEST(SmoothedGradient, FacetPointsIntegrateAQuadraticExactly) {
  const auto mesh = generate_mesh(test::box_spec(CellType::quad4, 4));  // h = 0.25
  const auto points = smoothing_points(mesh, {mesh.blocks[0].name});
  std::vector<double> integral(mesh.node_count(), 0.0);
  for (const auto& p : points) {
    const double f = p.x[0] * p.x[1] * p.x[1];
    integral[static_cast<std::size_t>(p.plus)] += f * p.weighted_normal[0];
    if (p.minus >= 0) integral[static_cast<std::size_t>(p.minus)] -= f * p.weighted_normal[0];
  }
  const double h = 0.25;
  int interior = 0;
  for (std::size_t n = 0; n < mesh.node_count(); ++n) {
    const double x = mesh.coordinates[2 * n], y = mesh.coordinates[2 * n + 1];
    if (x < 1e-12 || x > 2 - 1e-12 || y < 1e-12 || y > 1 - 1e-12) continue;
    ++interior;
    EXPECT_NEAR(integral[n], h * (y * y * h + h * h * h / 12), 1e-15)
        << "node at " << x << ", " << y;
  }
  EXPECT_EQ(interior, 7 * 3);
}

// The one-point rule of a flat facet, by hand: the trapezoid (0,0), (2,0), (1,1), (0,1) in z = 0
// is the unit square (centroid (1/2, 1/2)) and the triangle (1,0), (2,0), (1,1) (area 1/2,
// centroid (4/3, 1/3)): area 3/2 at (7/9, 4/9). Its vertex average (3/4, 1/2) would integrate
// x n wrongly. A warped facet (one corner lifted) gets no single point.
TEST(SmoothedGradient, FlatFacetPointIsTheAreaCentroid) {
  SmoothingPoint p;
  ASSERT_TRUE(flat_facet_point({{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, p));
  EXPECT_NEAR(p.x[0], 7.0 / 9.0, 1e-15);
  EXPECT_NEAR(p.x[1], 4.0 / 9.0, 1e-15);
  EXPECT_NEAR(p.x[2], 0.0, 1e-15);
  EXPECT_NEAR(p.weighted_normal[0], 0.0, 1e-15);
  EXPECT_NEAR(p.weighted_normal[1], 0.0, 1e-15);
  EXPECT_NEAR(p.weighted_normal[2], 1.5, 1e-15);
  // Tilted into a general plane (a rotation keeps it flat): still one point, at the rotated
  // centroid.
  const double c = std::cos(0.7), s = std::sin(0.7);
  auto tilt = [&](double x, double y) { return std::array<double, 3>{x, c * y, s * y}; };
  ASSERT_TRUE(flat_facet_point({{tilt(0, 0), tilt(2, 0), tilt(1, 1), tilt(0, 1)}}, p));
  EXPECT_NEAR(p.x[1], c * 4.0 / 9.0, 1e-15);
  EXPECT_NEAR(p.x[2], s * 4.0 / 9.0, 1e-15);
  EXPECT_FALSE(flat_facet_point({{{0, 0, 0}, {2, 0, 0}, {1, 1, 1e-3}, {0, 1, 0}}}, p));
}

// Which facets get one point: all of them in 2D (segments) and in tetrahedra (the facet of an
// edge spans the edge's midpoint and the centroids of its two sides and of the cell, which lie
// in one plane), every facet of an undistorted hex grid, and few of a perturbed one (warped:
// two points each, the triangles on a diagonal).
TEST(SmoothedGradient, CentroidRuleMergesFlatFacetsAndHalvesWarpedOnes) {
  auto inside = [](CellType type, double perturbation, SmoothingQuadrature rule) {
    const auto mesh = generate_mesh(test::box_spec(type, 3, perturbation, 17));
    std::size_t count = 0;
    for (const auto& p : smoothing_points(mesh, {mesh.blocks[0].name}, {}, nullptr, false, rule))
      count += p.minus >= 0;
    return count;
  };
  const auto split = SmoothingQuadrature::split, centroid = SmoothingQuadrature::centroid;
  for (auto type : {CellType::quad4, CellType::tri3})
    EXPECT_EQ(2 * inside(type, 0.3, centroid), inside(type, 0.3, split)) << cell_scene_name(type);
  EXPECT_EQ(4 * inside(CellType::tet4, 0.3, centroid), inside(CellType::tet4, 0.3, split));
  EXPECT_EQ(4 * inside(CellType::hex8, 0.0, centroid), inside(CellType::hex8, 0.0, split));
  const auto warped = inside(CellType::hex8, 0.3, centroid);
  EXPECT_LE(2 * warped, inside(CellType::hex8, 0.3, split));
  EXPECT_GT(2 * warped, inside(CellType::hex8, 0.3, split) * 9 / 10);

  // SCNI subcells (every side emitted, split among its nodes), 6 x 3 x 3 regular hexes, by hand:
  // 54 cells x (12 edge facets + 6 sides x 4 node quarters); 90 sides on the part's boundary.
  // Split: 54 x 48 + 324 x 16 = 7,776 points; centroid: 54 x 12 + 234 x 4 (sides inside) + 90 x 16
  // (the boundary keeps the split rule) = 3,024.
  const auto mesh = generate_mesh(test::box_spec(CellType::hex8, 3));
  EXPECT_EQ(smoothing_points(mesh, {mesh.blocks[0].name}, {}, nullptr, true, split).size(), 7776u);
  EXPECT_EQ(smoothing_points(mesh, {mesh.blocks[0].name}, {}, nullptr, true, centroid).size(),
            3024u);
}

// smoothing_quadrature: auto takes one point per flat facet only where it costs nothing
// measurable: plain SCNI, linear basis, 3D. The 2D, quadratic-basis and subcell cases keep the
// split rule, and a rule named in the scene is kept as named.
TEST(SmoothedGradient, AutoRuleIsCentroidForPlainLinearScniIn3DOnly) {
  SectionSpec section;  // the defaults: auto, linear basis, scni
  EXPECT_EQ(facet_rule(section, 3), SmoothingQuadrature::centroid);
  EXPECT_EQ(facet_rule(section, 2), SmoothingQuadrature::split);
  section.basis = Basis::quadratic;
  EXPECT_EQ(facet_rule(section, 3), SmoothingQuadrature::split);
  section.basis = Basis::linear;
  section.integration = Integration::scni_subcells;
  EXPECT_EQ(facet_rule(section, 3), SmoothingQuadrature::split);
  section.smoothing_quadrature = SmoothingQuadrature::centroid;
  EXPECT_EQ(facet_rule(section, 3), SmoothingQuadrature::centroid);
  section.integration = Integration::scni;
  section.smoothing_quadrature = SmoothingQuadrature::split;
  EXPECT_EQ(facet_rule(section, 3), SmoothingQuadrature::split);
  section.smoothing_quadrature = SmoothingQuadrature::centroid;
  EXPECT_EQ(facet_rule(section, 2), SmoothingQuadrature::centroid);
}

// The boundary rule of one side: the same exactness for a cubic along a side from (0, 0) to
// (2, 0): integral of x^3 = 4, of x^2 = 8/3.
TEST(SmoothedGradient, SidePointsIntegrateACubicExactly) {
  const auto points = side_smoothing_points({{{0, 0, 0}}, {{2, 0, 0}}}, {0, 1}, 2);
  double cubic = 0, square = 0;
  for (const auto& p : points) {
    const double w = std::hypot(p.weighted_normal[0], p.weighted_normal[1]);
    cubic += w * p.x[0] * p.x[0] * p.x[0];
    square += w * p.x[0] * p.x[0];
  }
  EXPECT_NEAR(cubic, 4.0, 1e-14);
  EXPECT_NEAR(square, 8.0 / 3.0, 1e-14);
}

}  // namespace
}  // namespace efg
