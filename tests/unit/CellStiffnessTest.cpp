// The background cells' finite element stiffness (operators/CellStiffness, the auxiliary space
// of the iterative solver) on distorted cells of every type: rigid-body motions carry no force
// (translations and infinitesimal rotations are in its null space), and a uniform strain eps
// stores the energy eps : C : eps V / 2 of the cell's volume V (the isoparametric elements are
// exact for linear fields; V from the divergence theorem on the reference rule). Fails when
// the shape gradients or the Jacobian are wrong (a 3D Jacobian started from the 2D identity
// gave 4.1x and 1.9x the diagonal).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mesh/GaussRules.hpp"
#include "operators/CellStiffness.hpp"

namespace efg {
namespace {

std::vector<double> distorted_cell(CellType type) {
  auto x = reference_corners(type);
  const int dim = cell_dimension(type);
  // an affine map plus a small nonlinear wobble per node (keeps the cell valid)
  for (std::size_t a = 0; a < x.size() / static_cast<std::size_t>(dim); ++a) {
    double* p = &x[a * static_cast<std::size_t>(dim)];
    const double q0 = p[0], q1 = p[1], q2 = dim == 3 ? p[2] : 0.0;
    p[0] = 1.3 * q0 + 0.2 * q1 + 0.05 * std::sin(3.0 * static_cast<double>(a));
    p[1] = -0.1 * q0 + 0.9 * q1 + 0.1 * q2 + 0.04 * std::cos(2.0 * static_cast<double>(a));
    if (dim == 3) p[2] = 0.15 * q0 + 1.1 * q2 + 0.03 * std::sin(5.0 * static_cast<double>(a));
  }
  return x;
}

double volume(CellType type, const std::vector<double>& x) {
  const auto rule = reference_rule(type, 2);
  const int dim = cell_dimension(type);
  double v = 0, point[3];
  for (std::size_t q = 0; q < rule.weight.size(); ++q)
    v += rule.weight[q] *
         map_to_cell(type, x.data(), &rule.xi[q * static_cast<std::size_t>(dim)], point);
  return v;
}

class CellStiffnessOf : public ::testing::TestWithParam<CellType> {};

TEST_P(CellStiffnessOf, RigidMotionsCarryNoForceAndUniformStrainItsEnergy) {
  const auto type = GetParam();
  const int dim = cell_dimension(type), n = cell_node_count(type), size = n * dim;
  const auto x = distorted_cell(type);
  const double lambda = 1.7, mu = 0.8;
  std::vector<double> ke;
  cell_stiffness(type, x.data(), lambda, mu, 1.0, ke);
  ASSERT_EQ(ke.size(), static_cast<std::size_t>(size * size));
  double largest = 0;
  for (double k : ke) largest = std::max(largest, std::abs(k));
  const auto force = [&](const std::vector<double>& u, int row) {
    double f = 0;
    for (int c = 0; c < size; ++c)
      f += ke[static_cast<std::size_t>(row * size + c)] * u[static_cast<std::size_t>(c)];
    return f;
  };
  // u = t + W x for a translation t and a skew W (all three axes in 3D, one in 2D)
  std::vector<std::vector<double>> rigid;
  for (int d = 0; d < dim; ++d) {
    std::vector<double> u(static_cast<std::size_t>(size), 0.0);
    for (int a = 0; a < n; ++a) u[static_cast<std::size_t>(a * dim + d)] = 1.0;
    rigid.push_back(u);
  }
  const int axes[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int r = 0; r < (dim == 3 ? 3 : 1); ++r) {
    std::vector<double> u(static_cast<std::size_t>(size), 0.0);
    const int i = axes[r][0], j = axes[r][1];
    for (int a = 0; a < n; ++a) {
      u[static_cast<std::size_t>(a * dim + i)] = -x[static_cast<std::size_t>(a * dim + j)];
      u[static_cast<std::size_t>(a * dim + j)] = x[static_cast<std::size_t>(a * dim + i)];
    }
    rigid.push_back(u);
  }
  for (const auto& u : rigid)
    for (int row = 0; row < size; ++row) EXPECT_NEAR(force(u, row), 0.0, 1e-12 * largest);
  // u = eps x with a symmetric eps: energy u.K.u / 2 = (lambda tr(eps)^2 / 2 + mu eps:eps) V
  const double e[3][3] = {{0.3, 0.1, -0.05}, {0.1, -0.2, 0.07}, {-0.05, 0.07, 0.15}};
  std::vector<double> u(static_cast<std::size_t>(size), 0.0);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        u[static_cast<std::size_t>(a * dim + i)] +=
            e[i][j] * x[static_cast<std::size_t>(a * dim + j)];
  double uku = 0;
  for (int row = 0; row < size; ++row) uku += u[static_cast<std::size_t>(row)] * force(u, row);
  double trace = 0, contraction = 0;
  for (int i = 0; i < dim; ++i) {
    trace += e[i][i];
    for (int j = 0; j < dim; ++j) contraction += e[i][j] * e[i][j];
  }
  const double expected = (lambda * trace * trace / 2 + mu * contraction) * volume(type, x);
  EXPECT_NEAR(uku / 2, expected, 1e-12 * std::abs(expected));
}

INSTANTIATE_TEST_SUITE_P(AllCells, CellStiffnessOf,
                         ::testing::Values(CellType::quad4, CellType::tri3, CellType::hex8,
                                           CellType::tet4, CellType::wedge6),
                         [](const auto& p) { return cell_scene_name(p.param); });

}  // namespace
}  // namespace efg
