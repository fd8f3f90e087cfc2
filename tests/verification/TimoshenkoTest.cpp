// Timoshenko cantilever (../shared/reference/benchmarks.md): L = 48, D = 12, E = 3e7, nu = 0.3,
// P = 1000, plane stress; exact displacement imposed on x = 0, exact traction on x = L (and the
// traction-free long sides). Linear basis, SCNI, dilation 2: L2 displacement error O(h^2),
// energy O(h) (least-squares slopes over 4 levels, h = 3 to 0.375).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/Log.hpp"
#include "support/BeamScene.hpp"
#include "support/StaticSolve.hpp"
#include "verification/ErrorNorms.hpp"

namespace efg {
namespace {

struct Level {
  double h, l2, energy, tip;
};

std::vector<Level> series(double perturbation, const char* method, const char* basis,
                          double dilation) {
  std::vector<Level> levels;
  for (int ny : {4, 8, 16, 32}) {
    auto s = test::solve_static(
        test::beam_scene(4 * ny, ny, perturbation, method, basis, "scni", dilation));
    const auto exact = make_exact_solution(s.model->scene, 2);
    const auto e = error_norms(*s.model, s.problem->solid(), *s.d_overlap, exact);
    const double tip_point[3] = {48.0, 0.0, 0.0};
    const auto tip = displacement_at(*s.model, s.problem->solid(), *s.d_overlap, tip_point);
    levels.push_back({12.0 / ny, e.l2_relative, e.energy_relative, tip[1]});
    std::ostringstream o;
    o << "timoshenko " << method << " " << basis << " perturbation " << perturbation
      << ": h = " << 12.0 / ny << "  L2 " << e.l2_relative << "  energy " << e.energy_relative
      << "  tip u_y " << tip[1];
    Log::info(o.str());
  }
  return levels;
}

// Least-squares slope of log(error) against log(h).
double rate(const std::vector<Level>& levels, double Level::*error) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(levels.size());
  for (const auto& l : levels) {
    const double x = std::log(l.h), y = std::log(l.*error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

class Timoshenko : public ::testing::TestWithParam<double> {};

TEST_P(Timoshenko, LinearBasisScniConvergesAtTheExpectedRates) {
  const auto levels = series(GetParam(), "transformation", "linear", 2.0);
  const double l2_rate = rate(levels, &Level::l2), energy_rate = rate(levels, &Level::energy);
  Log::info("  rates: L2 " + std::to_string(l2_rate) + ", energy " + std::to_string(energy_rate));
  EXPECT_GE(l2_rate, 1.9);
  EXPECT_GE(energy_rate, 0.95);
  EXPECT_NEAR(levels[2].tip, 0.0089, 0.005 * 0.0089) << "tip deflection on the second-finest level";
  for (std::size_t i = 1; i < levels.size(); ++i) EXPECT_LT(levels[i].l2, levels[i - 1].l2);
}

TEST(TimoshenkoReaction, ClampReactionBalancesTheTipLoad) {
  for (const char* method : {"transformation", "nitsche", "penalty"}) {
    auto s = test::solve_static(test::beam_scene(32, 8, 0.2, method, "linear", "scni", 2.0));
    const auto r = s.problem->reactions(*s.d)[0];
    EXPECT_NEAR(r[1], -1000.0, 1.0) << method;  // the support holds the 1000 shear load
    EXPECT_NEAR(r[0], 0.0, 1.0) << method;
  }
}

INSTANTIATE_TEST_SUITE_P(RegularAndPerturbed, Timoshenko, ::testing::Values(0.0, 0.2),
                         [](const auto& p) {
                           return p.param == 0.0 ? std::string("regular")
                                                 : std::string("perturbed");
                         });

}  // namespace
}  // namespace efg
