// Expressions in scene values (issue 19): compiled values, parameters, errors with positions, and
// the built-in exact solutions written as expressions equal to their C++ closed forms (item 4).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "core/Errors.hpp"
#include "expressions/Expression.hpp"
#include "model/ExactSolutions.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

constexpr auto kXT = ExpressionVariables::position_and_time;

TEST(Expression, EvaluatesVariablesParametersAndFunctions) {
  const Expression e("a*x^2 + sin(pi*y/2) + atan2(z, 1) - 3*t", {{"a", 2.0}}, kXT);
  const double p[3] = {1.5, 1.0, 0.5};
  // hand value: 2 * 2.25 + sin(pi/2) + atan(0.5 / 1) - 3 * 0.5 (z != 1: atan2's argument order
  // matters)
  EXPECT_NEAR(e(p, 0.5), 4.5 + 1.0 + std::atan(0.5) - 1.5, 1e-15);
  EXPECT_TRUE(e.uses_position());
  EXPECT_TRUE(e.uses_time());
  const Expression c("2*a + ln(_e)", {{"a", 3.0}}, ExpressionVariables::none);
  EXPECT_FALSE(c.uses_position());
  EXPECT_DOUBLE_EQ(c(), 7.0);
  EXPECT_TRUE(std::isinf(Expression("1/x", {}, kXT)(std::array<double, 3>{0, 0, 0}.data(), 0)));
}

int error_position(const std::string& text, ExpressionVariables v = kXT) {
  try {
    Expression(text, {{"a", 1.0}}, v);
  } catch (const ExpressionError& e) {
    return e.position();
  }
  return -100;  // compiled: no error
}

TEST(Expression, ErrorsPointAtTheFaultyCharacter) {
  EXPECT_EQ(error_position("2*q"), 2);                                   // unknown name
  EXPECT_EQ(error_position("x + t", ExpressionVariables::position), 4);  // t not allowed here
  EXPECT_EQ(error_position("2**x"), 2);                                  // operator after operator
  EXPECT_EQ(error_position("x = 1"), 2);                                 // assignment
  EXPECT_EQ(error_position("(x+1))"), 5);                                // unbalanced ')'
  EXPECT_EQ(error_position("1, 2"), 1);                                  // two values
  EXPECT_EQ(error_position(" "), 0);                                     // empty
  EXPECT_EQ(error_position("x <= a"), -100);                             // comparisons compile
}

// A 2D scene with a built-in exact solution and the same one as user expressions.
Scene scene_with(const std::string& verification, const std::string& material = "nu: 0.3",
                 const std::string& plane = "stress") {
  const std::string text = R"(parameters: {L: 48, D: 12, P: 1000, E: 3.0e7, nu: 0.3, I: "D^3/12"}
mesh:
  generate: {element: quad4, lower: [0, -6], upper: [48, 6], cells: [4, 2]}
parts:
  - {name: p, blocks: [block_1], material: m, plane: )" +
                           plane + R"(}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 3.0e7, poissons_ratio: )" +
                           material.substr(4) + R"(}
verification:
)" + verification;
  return parse_scene(text, "expressions.yaml");
}

void expect_equal(const ExactSolution& a, const ExactSolution& b, double scale_u, double scale_s) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(0.0, 48.0), y(-6.0, 6.0);
  for (int k = 0; k < 100; ++k) {
    const double X[3] = {x(random), y(random), 0.0};
    double ua[3] = {0, 0, 0}, ub[3] = {0, 0, 0}, sa[3][3], sb[3][3];
    a.displacement(X, ua);
    b.displacement(X, ub);
    a.nominal_stress(X, sa);
    b.nominal_stress(X, sb);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(ua[i], ub[i], 1e-12 * scale_u) << "u_" << i << " at " << X[0] << ", " << X[1];
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(sa[i][j], sb[i][j], 1e-12 * scale_s);
    }
    if (a.body_force) {
      double ba[3] = {0, 0, 0}, bb[3] = {0, 0, 0};
      a.body_force(X, ba);
      b.body_force(X, bb);
      EXPECT_NEAR(ba[0], bb[0], 1e-12 * 48);
    }
  }
}

TEST(Expression, TimoshenkoBeamEqualsItsExpressions) {
  const auto builtin = make_exact_solution(
      // the built-in's parameters given by the scene's parameters (any number may be one)
      scene_with("  exact_solution: timoshenko_beam\n  parameters: {length: L, depth: \"2*D/2\", "
                 "load: P}\n"),
      2);
  const auto user = make_exact_solution(scene_with(R"Y(  exact_solution: user
  user_solution:
    displacement:
      - "-P*y/(6*E*I)*((6*L-3*x)*x + (2+nu)*(y*y-D*D/4))"
      - "P/(6*E*I)*(3*nu*y*y*(L-x) + (4+5*nu)*D*D*x/4 + (3*L-x)*x*x)"
    stress: {xx: "-P*(L-x)*y/I", yy: 0, xy: "P/(2*I)*(D*D/4-y*y)"}
)Y"),
                                        2);
  expect_equal(builtin, user, 0.01, 1000.0);
}

TEST(Expression, LinearPatchEqualsItsExpressionsWithTheElasticStress) {
  // The default gradient of linear_patch in 2D: G = 1e-3 [[1, -2], [3, -4]]; the user solution
  // gives only u, so its stress comes from the plane-stress law by central differences.
  const auto builtin = make_exact_solution(scene_with("  exact_solution: linear_patch\n"), 2);
  const auto user = make_exact_solution(scene_with(R"Y(  exact_solution: user
  user_solution:
    displacement: ["1e-3*(x - 2*y)", "1e-3*(3*x - 4*y)"]
)Y"),
                                        2);
  std::mt19937 random(3);
  for (int k = 0; k < 20; ++k) {
    const double X[3] = {48.0 * k / 20.0, -6.0 + 0.5 * k, 0.0};
    double sa[3][3], sb[3][3], ua[3], ub[3];
    builtin.displacement(X, ua);
    user.displacement(X, ub);
    builtin.nominal_stress(X, sa);
    user.nominal_stress(X, sb);
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(ua[i], ub[i], 1e-15);
      // central differences of a linear field are exact up to the round-off of u / h (1e-6)
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(sa[i][j], sb[i][j], 1e-7 * 3e7 * 1e-3);
    }
  }
}

TEST(Expression, Bar1dEqualsItsExpressions) {
  const auto builtin =
      make_exact_solution(scene_with("  exact_solution: bar_1d\n", "nu: 0.0", "strain"), 2);
  const auto user = make_exact_solution(scene_with(R"Y(  exact_solution: user
  user_solution:
    displacement: ["(x/2 - x^3/6)/E", 0]
    stress: {xx: "0.5 - x^2/2", yy: 0, xy: 0}
    body_force: [x, 0]
)Y",
                                                   "nu: 0.0", "strain"),
                                        2);
  expect_equal(builtin, user, 48.0 * 48.0 * 48.0 / 3e7, 48.0 * 48.0);
}

TEST(Expression, HomogeneousStretchEqualsItsExpressions) {
  // Linear elastic, plane strain, stretches 1.01 and 0.98: P_ii = lambda tr(eps) + 2 mu eps_ii.
  const auto builtin = make_exact_solution(
      scene_with("  exact_solution: homogeneous_stretch\n  parameters: {stretch: [1.01, 0.98]}\n",
                 "nu: 0.3", "strain"),
      2);
  const auto user = make_exact_solution(scene_with(R"Y(  exact_solution: user
  user_solution:
    displacement: ["0.01*x", "-0.02*y"]
    stress:
      xx: "E*nu/((1 + nu)*(1 - 2*nu))*(0.01 - 0.02) + E/(1 + nu)*0.01"
      yy: "E*nu/((1 + nu)*(1 - 2*nu))*(0.01 - 0.02) - E/(1 + nu)*0.02"
      xy: 0
)Y",
                                                   "nu: 0.3", "strain"),
                                        2);
  expect_equal(builtin, user, 1.0, 1e6);
}

TEST(Expression, UserSolutionOfTheWrongDimensionIsAnInputError) {
  const auto scene = scene_with(R"Y(  exact_solution: user
  user_solution:
    displacement: [x, y, 0]
)Y");
  EXPECT_THROW(make_exact_solution(scene, 2), InputError);
}

}  // namespace
}  // namespace efg
