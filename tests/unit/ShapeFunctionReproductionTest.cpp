// Reproducing conditions of the MLS shape functions (Belytschko, Lu, Gu 1994): a basis of order
// k reproduces every polynomial of degree <= k and its gradient exactly, at any point, on any
// node set whose moment matrices are regular.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "discretization/ShapeFunctions.hpp"
#include "support/Clouds.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

using Config = std::tuple<int /*dim*/, KernelType, SupportShape, Basis, bool /*perturbed*/>;

// Monomials up to degree 2 and their gradients, for the reproduction checks.
struct Monomial {
  int i, j;  // x_i x_j; j = -1 for x_i alone; i = -1 for the constant
  double value(const double* x) const { return (i < 0 ? 1.0 : x[i]) * (j < 0 ? 1.0 : x[j]); }
  double derivative(const double* x, int d) const {
    if (i < 0) return 0.0;
    if (j < 0) return d == i ? 1.0 : 0.0;
    return (d == i ? x[j] : 0.0) + (d == j ? x[i] : 0.0);
  }
};

std::vector<Monomial> monomials(int dim, Basis basis) {
  std::vector<Monomial> m = {{-1, -1}};
  for (int i = 0; i < dim; ++i) m.push_back({i, -1});
  if (basis == Basis::quadratic)
    for (int i = 0; i < dim; ++i)
      for (int j = i; j < dim; ++j) m.push_back({i, j});
  return m;
}

class Reproduction : public ::testing::TestWithParam<Config> {};

TEST_P(Reproduction, PolynomialsAndGradientsToRoundOff) {
  const auto [dim, kernel, support, basis, perturbed] = GetParam();
  SectionSpec section;
  section.kernel = kernel;
  section.support = support;
  section.basis = basis;
  // Enough neighbours for a regular moment matrix: quadratic bases and spheres need more.
  section.dilation = {basis == Basis::quadratic ? 2.6
                                                : (support == SupportShape::sphere ? 2.1 : 1.6)};
  const double perturbation = perturbed ? 0.3 : 0.0;
  ParticleCloud cloud;
  std::array<double, 3> lower{0, 0, 0}, upper{1, 1, 1};
  if (dim == 1) {
    cloud = test::line_cloud(20, perturbation, section);
  } else {
    auto spec = test::box_spec(dim == 2 ? CellType::quad4 : CellType::hex8, dim == 2 ? 8 : 4,
                               perturbation, 21);
    upper = spec.upper;
    cloud = test::mesh_cloud(generate_mesh(spec), section);
  }
  const std::size_t count = 1000;
  const auto points = test::random_points(dim, lower, upper, count, 99);
  const auto v = evaluate_shape_functions(cloud, points.data(), count, true);
  EXPECT_EQ(v.ill_conditioned, 0u);
  const auto d = static_cast<std::size_t>(dim);
  double worst_value = 0, worst_gradient = 0;
  for (const auto& m : monomials(dim, basis)) {
    for (std::size_t p = 0; p < count; ++p) {
      const double* x = &points[p * d];
      double value = 0, gradient[3] = {0, 0, 0};
      for (auto k = v.neighbors.offsets[p]; k < v.neighbors.offsets[p + 1]; ++k) {
        const auto* xi = cloud.x(static_cast<std::size_t>(v.neighbors.particles[k]));
        value += v.phi[k] * m.value(xi);
        for (std::size_t e = 0; e < d; ++e) gradient[e] += v.grad[k * d + e] * m.value(xi);
      }
      // Relative to the size of the field over the domain (at most 2^2 = 4 here) and of its gradient.
      worst_value = std::max(worst_value, std::abs(value - m.value(x)) / 4.0);
      for (std::size_t e = 0; e < d; ++e)
        worst_gradient = std::max(
            worst_gradient, std::abs(gradient[e] - m.derivative(x, static_cast<int>(e))) / 4.0);
    }
  }
  EXPECT_LT(worst_value, 1e-12);
  EXPECT_LT(worst_gradient, 1e-12);
}

std::string name(const ::testing::TestParamInfo<Config>& info) {
  const auto [dim, kernel, support, basis, perturbed] = info.param;
  const char* k = kernel == KernelType::cubic_spline     ? "cubic"
                  : kernel == KernelType::quartic_spline ? "quartic"
                                                         : "quadratic";
  return std::to_string(dim) + "d_" + k + (support == SupportShape::box ? "_box" : "_sphere") +
         (basis == Basis::linear ? "_linear" : "_quadraticbasis") +
         (perturbed ? "_perturbed" : "_regular");
}

INSTANTIATE_TEST_SUITE_P(
    AllCombinations, Reproduction,
    ::testing::Combine(::testing::Values(1, 2, 3),
                       ::testing::Values(KernelType::cubic_spline, KernelType::quadratic_spline,
                                         KernelType::quartic_spline),
                       ::testing::Values(SupportShape::box, SupportShape::sphere),
                       ::testing::Values(Basis::linear, Basis::quadratic),
                       ::testing::Values(false, true)),
    name);

TEST(ShapeFunctions, PartitionOfUnityOfTheWeightsMatchesKernelAtNodesForLinearBasis) {
  // In 1D with dilation just above 1 (only the two nearest particles), linear MLS reduces to
  // linear interpolation between them: phi_I(x) = (x_J - x) / (x_J - x_I).
  SectionSpec section;
  section.dilation = {1.01};
  const auto cloud = test::line_cloud(10, 0.0, section);
  const double x = 0.537;
  const auto v = evaluate_shape_functions(cloud, &x, 1, true);
  ASSERT_EQ(v.neighbors.count(0), 2u);
  EXPECT_NEAR(v.phi[0], (0.6 - x) / 0.1, 1e-13);
  EXPECT_NEAR(v.phi[1], (x - 0.5) / 0.1, 1e-13);
  EXPECT_NEAR(v.grad[0], -10.0, 1e-11);
}

}  // namespace
}  // namespace efg
