// Material kernels: P is the derivative of the strain energy, A the derivative of P (central
// finite differences), and the neo-Hookean Cauchy stress matches its closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/ElasticConstants.hpp"
#include "materials/SolidMaterial.hpp"

namespace efg::physics {
namespace {

template <int Dim>
void check_derivatives(const SolidMaterial& m, const double (&H)[Dim][Dim]) {
  double P[Dim][Dim], A[Dim][Dim][Dim][Dim];
  ASSERT_TRUE(stress_and_tangent<Dim>(m, H, P, A));
  const double h = 1e-6;
  double worst_p = 0, worst_a = 0, scale_p = 0, scale_a = 0;
  for (int k = 0; k < Dim; ++k)
    for (int l = 0; l < Dim; ++l) {
      double Hp[Dim][Dim], Hm[Dim][Dim];
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) Hp[i][j] = Hm[i][j] = H[i][j];
      Hp[k][l] += h;
      Hm[k][l] -= h;
      const double dW = (strain_energy<Dim>(m, Hp) - strain_energy<Dim>(m, Hm)) / (2 * h);
      worst_p = std::max(worst_p, std::abs(dW - P[k][l]));
      scale_p = std::max(scale_p, std::abs(P[k][l]));
      double Pp[Dim][Dim] = {}, Pm[Dim][Dim] = {}, Ap[Dim][Dim][Dim][Dim] = {};
      ASSERT_TRUE(stress_and_tangent<Dim>(m, Hp, Pp, Ap));
      ASSERT_TRUE(stress_and_tangent<Dim>(m, Hm, Pm, Ap));
      for (int i = 0; i < Dim; ++i)
        for (int j = 0; j < Dim; ++j) {
          worst_a = std::max(worst_a, std::abs((Pp[i][j] - Pm[i][j]) / (2 * h) - A[i][j][k][l]));
          scale_a = std::max(scale_a, std::abs(A[i][j][k][l]));
        }
    }
  EXPECT_LT(worst_p, 1e-7 * scale_p);
  EXPECT_LT(worst_a, 1e-7 * scale_a);
}

TEST(SolidMaterial, StressIsTheEnergyGradientAndTangentTheStressGradient) {
  const auto c = elastic_constants(200.0, 0.3);
  for (auto kind : {MaterialKind::linear_elastic, MaterialKind::neo_hookean,
                    MaterialKind::isochoric_neo_hookean}) {
    const SolidMaterial m{kind, c.lambda, c.mu, false};
    check_derivatives<3>(m, {{0.3, 0.1, -0.05}, {0.02, -0.2, 0.1}, {0.07, 0.04, 0.15}});
    check_derivatives<2>(m, {{0.3, 0.1}, {-0.05, -0.2}});
  }
}

TEST(SolidMaterial, NeoHookeanCauchyStressOfAStretch) {
  // F = diag(2, 0.8, 0.8): sigma = 1/J (mu (b - I) + lambda ln J I) with J = 1.28. E = 10,
  // nu = 0.45 by hand: mu = 10 / 2.9, lambda = 4.5 / (1.45 x 0.1).
  struct {
    double lambda = 4.5 / 0.145, mu = 10.0 / 2.9;
  } c;
  const SolidMaterial m{MaterialKind::neo_hookean, c.lambda, c.mu, false};
  const double H[3][3] = {{1.0, 0, 0}, {0, -0.2, 0}, {0, 0, -0.2}};
  double s[3][3];
  cauchy_stress<3>(m, H, s);
  const double J = 2.0 * 0.8 * 0.8;
  EXPECT_NEAR(s[0][0], (c.mu * (4.0 - 1.0) + c.lambda * std::log(J)) / J, 1e-12);
  EXPECT_NEAR(s[1][1], (c.mu * (0.64 - 1.0) + c.lambda * std::log(J)) / J, 1e-12);
  EXPECT_EQ(s[0][1], 0.0);
  // Cauchy = P F^T / J.
  double P[3][3], A[3][3][3][3];
  ASSERT_TRUE(stress_and_tangent<3>(m, H, P, A));
  EXPECT_NEAR(P[0][0] * 2.0 / J, s[0][0], 1e-12);
}

// The isochoric part of mixed u-p parts: no energy or stress from a volume change (W(s F) =
// W(F), a pure dilation F = s I gives P = 0), the Cauchy stress is traceless and equals P F^T / J
// (F = diag(2, 0.8, 0.8) by hand: sigma = mu J^(-5/3) dev(b)).
TEST(SolidMaterial, IsochoricNeoHookeanIgnoresVolumeChange) {
  const SolidMaterial m{MaterialKind::isochoric_neo_hookean, 0.0, 3.0, false};
  const double H[3][3] = {{1.0, 0.1, 0}, {0, -0.2, 0.05}, {0.02, 0, -0.2}};
  double scaled[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) scaled[i][j] = 1.7 * (H[i][j] + (i == j)) - (i == j);
  EXPECT_NEAR(strain_energy<3>(m, scaled), strain_energy<3>(m, H), 1e-12);
  const double dilation[3][3] = {{0.3, 0, 0}, {0, 0.3, 0}, {0, 0, 0.3}};
  double P[3][3], s[3][3];
  ASSERT_TRUE(stress<3>(m, dilation, P));
  for (auto& row : P)
    for (double v : row) EXPECT_NEAR(v, 0.0, 1e-14);
  const double stretch[3][3] = {{1.0, 0, 0}, {0, -0.2, 0}, {0, 0, -0.2}};
  cauchy_stress<3>(m, stretch, s);
  const double J = 2.0 * 0.8 * 0.8, I1 = 4.0 + 2 * 0.64;
  EXPECT_NEAR(s[0][0], 3.0 * std::pow(J, -5.0 / 3.0) * (4.0 - I1 / 3.0), 1e-12);
  EXPECT_NEAR(s[0][0] + s[1][1] + s[2][2], 0.0, 1e-12);
  ASSERT_TRUE(stress<3>(m, stretch, P));
  EXPECT_NEAR(P[0][0] * 2.0 / J, s[0][0], 1e-12);
}

TEST(SolidMaterial, InvertedPointIsReported) {
  const SolidMaterial m{MaterialKind::neo_hookean, 1.0, 1.0, false};
  const double H[2][2] = {{-1.5, 0}, {0, 0}};  // F_11 = -0.5
  double P[2][2], A[2][2][2][2];
  EXPECT_FALSE(stress_and_tangent<2>(m, H, P, A));
}

TEST(SolidMaterial, VonMisesOfUniaxialStressIsItsMagnitude) {
  const double s[3][3] = {{-7.0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  EXPECT_DOUBLE_EQ(von_mises(s), 7.0);
}

}  // namespace
}  // namespace efg::physics
