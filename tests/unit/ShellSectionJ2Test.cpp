// J2 through the thickness of a Reissner-Mindlin section (physics/materials/ShellSectionJ2.hpp)
// and the Gauss rule it integrates with, against hand values: the rule integrates polynomials of
// degree 2n - 1 exactly; an elastic section gives A eps and D kappa; equibiaxial bending of an
// elastic-perfectly plastic section gives at each layer sigma = min(E / (1 - nu) z kappa,
// sigma_y) (equibiaxial stress stays equibiaxial, and its von Mises stress is sigma itself), so
// the moment is that function's Gauss sum, and a fully plastic section sigma_y t^2 / 4 times
// sum_k w_k |xi_k|.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/ElasticConstants.hpp"
#include "materials/ShellSectionJ2.hpp"

namespace efg::physics {
namespace {

constexpr int S = j2_state::count;
const double E = 200.0, nu = 0.3, yield = 0.25, t = 0.1;

J2Parameters perfectly_plastic() {
  const auto lame = elastic_constants(E, nu);
  J2Parameters p = j2_linear_hardening(lame.lambda, lame.mu, yield, 0.0);
  p.curve_points = 0;  // perfect plasticity
  return p;
}

TEST(ThicknessRule, IntegratesPolynomialsOfDegreeTwoNMinusOneExactly) {
  for (int n = 1; n <= max_thickness_points; ++n) {
    double xi[max_thickness_points], w[max_thickness_points];
    ASSERT_EQ(thickness_rule(n, xi, w), n);
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      double sum = 0;
      for (int k = 0; k < n; ++k) sum += w[k] * std::pow(xi[k], degree);
      const double exact = degree % 2 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-14) << n << " points, degree " << degree;
    }
    for (int k = 1; k < n; ++k) EXPECT_LT(xi[k - 1], xi[k]);
  }
  // Abramowitz & Stegun table 25.4, five points
  double xi[max_thickness_points], w[max_thickness_points];
  thickness_rule(5, xi, w);
  EXPECT_NEAR(xi[4], 0.9061798459386640, 1e-15);
  EXPECT_NEAR(w[4], 0.2369268850561891, 1e-15);
  EXPECT_NEAR(w[2], 0.5688888888888889, 1e-15);
}

TEST(ShellSectionJ2, ElasticSectionGivesAEpsAndDKappa) {
  const auto section = elastic_mindlin_section(E, nu, t, 2);
  const double eps[3] = {1e-4, -3e-4, 2e-4}, kappa[3] = {2e-3, 1e-3, -4e-3};
  double old_states[5 * S] = {}, new_states[5 * S], N[3], M[3];
  j2_section_resultants(perfectly_plastic(), t, 5, eps, kappa, old_states, new_states, 0.0, N, M);
  for (int i = 0; i < 3; ++i) {
    double n = 0, m = 0;
    for (int j = 0; j < 3; ++j) {
      n += section.membrane[i][j] * eps[j];
      m += section.bending[i][j] * kappa[j];
    }
    EXPECT_NEAR(N[i], n, 1e-12 * std::abs(section.membrane[0][0] * 4e-4));
    EXPECT_NEAR(M[i], m, 1e-12 * std::abs(section.bending[0][0] * 4e-3));
  }
  for (int k = 0; k < 5; ++k) EXPECT_EQ(new_states[k * S + j2_state::alpha], 0.0);
}

TEST(ShellSectionJ2, EquibiaxialBendingFollowsTheLayersClosedForm) {
  const int n = 9;
  double xi[max_thickness_points], w[max_thickness_points];
  thickness_rule(n, xi, w);
  // curvature at which the outer layer z = t/2 yields, and three multiples of it
  const double kappa_y = yield * (1 - nu) / (E * t / 2);
  for (double factor : {0.5, 2.0, 5.0, 1e4}) {
    const double k = factor * kappa_y, eps[3] = {0, 0, 0}, kappa[3] = {k, k, 0};
    double old_states[n * S] = {}, new_states[n * S], N[3], M[3];
    j2_section_resultants(perfectly_plastic(), t, n, eps, kappa, old_states, new_states, 0.0, N, M);
    double expected = 0;
    for (int j = 0; j < n; ++j) {
      const double z = 0.5 * t * xi[j];
      const double sigma = std::copysign(std::min(E / (1 - nu) * std::abs(z) * k, yield), z);
      expected += sigma * z * 0.5 * t * w[j];
    }
    EXPECT_NEAR(M[0], expected, 1e-10 * yield * t * t) << factor;
    EXPECT_NEAR(M[1], expected, 1e-10 * yield * t * t) << factor;
    EXPECT_NEAR(M[2], 0.0, 1e-12 * yield * t * t);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(N[i], 0.0, 1e-12 * yield * t);
    // the outermost layers' stresses from the committed states (the output's top and bottom)
    double top[3], bottom[3];
    j2_layer_stress(perfectly_plastic(), t, n, n - 1, eps, kappa, new_states, top);
    j2_layer_stress(perfectly_plastic(), t, n, 0, eps, kappa, new_states, bottom);
    const double z = 0.5 * t * xi[n - 1];
    const double outer = std::min(E / (1 - nu) * z * k, yield);
    EXPECT_NEAR(top[0], outer, 1e-10 * yield) << factor;
    EXPECT_NEAR(top[1], outer, 1e-10 * yield) << factor;
    EXPECT_NEAR(bottom[0], -outer, 1e-10 * yield) << factor;
    EXPECT_NEAR(top[2], 0.0, 1e-12 * yield);
    if (factor > 100) {  // fully plastic: sigma_y t^2 / 4 sum_k w_k |xi_k|
      double q = 0;
      for (int j = 0; j < n; ++j) q += w[j] * std::abs(xi[j]);
      EXPECT_NEAR(M[0], yield * t * t / 4 * q, 1e-6 * yield * t * t);
      EXPECT_NEAR(q, 0.9816897567487616, 1e-14);  // numpy.polynomial.legendre.leggauss(9)
    }
  }
}

}  // namespace
}  // namespace efg::physics
