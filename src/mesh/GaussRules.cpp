#include "mesh/GaussRules.hpp"

#include <cmath>
#include <stdexcept>

#include "tensor/Tensor.hpp"

namespace efg {
namespace {

// Isoparametric shape functions and reference derivatives of each cell type.
int shape(CellType type, const double* xi, double* n, double (*dn)[3]) {
  const double r = xi[0], s = xi[1], t = cell_dimension(type) == 3 ? xi[2] : 0.0;
  switch (type) {
    case CellType::quad4: {
      const double c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int a = 0; a < 4; ++a) {
        n[a] = 0.25 * (1 + c[a][0] * r) * (1 + c[a][1] * s);
        dn[a][0] = 0.25 * c[a][0] * (1 + c[a][1] * s);
        dn[a][1] = 0.25 * c[a][1] * (1 + c[a][0] * r);
      }
      return 4;
    }
    case CellType::tri3:
      n[0] = 1 - r - s, n[1] = r, n[2] = s;
      dn[0][0] = -1, dn[0][1] = -1, dn[1][0] = 1, dn[1][1] = 0, dn[2][0] = 0, dn[2][1] = 1;
      return 3;
    case CellType::hex8: {
      const double c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                              {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
      for (int a = 0; a < 8; ++a) {
        n[a] = 0.125 * (1 + c[a][0] * r) * (1 + c[a][1] * s) * (1 + c[a][2] * t);
        dn[a][0] = 0.125 * c[a][0] * (1 + c[a][1] * s) * (1 + c[a][2] * t);
        dn[a][1] = 0.125 * c[a][1] * (1 + c[a][0] * r) * (1 + c[a][2] * t);
        dn[a][2] = 0.125 * c[a][2] * (1 + c[a][0] * r) * (1 + c[a][1] * s);
      }
      return 8;
    }
    case CellType::tet4:
      n[0] = 1 - r - s - t, n[1] = r, n[2] = s, n[3] = t;
      for (int a = 0; a < 4; ++a)
        for (int d = 0; d < 3; ++d) dn[a][d] = a == 0 ? -1.0 : (a - 1 == d ? 1.0 : 0.0);
      return 4;
    case CellType::wedge6: {
      const double l[3] = {1 - r - s, r, s};
      const double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
      for (int layer = 0; layer < 2; ++layer)
        for (int i = 0; i < 3; ++i) {
          const int a = 3 * layer + i;
          const double h = layer == 0 ? 0.5 * (1 - t) : 0.5 * (1 + t);
          n[a] = l[i] * h;
          dn[a][0] = dl[i][0] * h;
          dn[a][1] = dl[i][1] * h;
          dn[a][2] = l[i] * (layer == 0 ? -0.5 : 0.5);
        }
      return 6;
    }
  }
  throw std::logic_error("unknown cell type");
}

}  // namespace

void gauss_legendre(int n, std::vector<double>& points, std::vector<double>& weights) {
  if (n < 1 || n > 6) throw std::invalid_argument("Gauss-Legendre order must be 1..6");
  points.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  // Newton iteration on the Legendre polynomial P_n from the Chebyshev guess (Press et al.,
  // Numerical Recipes, gauleg): converges to machine precision in a few steps.
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = 0.0;
      for (int j = 1; j <= n; ++j) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * j - 1.0) * z * p1 - (j - 1.0) * p2) / j;
      }
      dp = n * (z * p0 - p1) / (z * z - 1.0);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    points[static_cast<std::size_t>(i)] = -z;
    weights[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
  }
}

ReferenceRule reference_rule(CellType type, int n) {
  std::vector<double> g, w;
  gauss_legendre(n, g, w);
  ReferenceRule rule;
  const auto m = g.size();
  auto add = [&](std::initializer_list<double> xi, double weight) {
    rule.xi.insert(rule.xi.end(), xi);
    rule.weight.push_back(weight);
  };
  // Collapsed coordinates: (u, v) in [-1,1]^2 -> triangle r = (1+u)(1-v)/4, s = (1+v)/2 with
  // Jacobian (1-v)/8; (u, v, w) -> tet likewise with Jacobian (1-v)(1-w)^2/64.
  switch (type) {
    case CellType::quad4:
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j) add({g[i], g[j]}, w[i] * w[j]);
      break;
    case CellType::hex8:
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
          for (std::size_t k = 0; k < m; ++k) add({g[i], g[j], g[k]}, w[i] * w[j] * w[k]);
      break;
    case CellType::tri3:
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
          add({(1 + g[i]) * (1 - g[j]) / 4, (1 + g[j]) / 2}, w[i] * w[j] * (1 - g[j]) / 8);
      break;
    case CellType::wedge6:
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
          for (std::size_t k = 0; k < m; ++k)
            add({(1 + g[i]) * (1 - g[j]) / 4, (1 + g[j]) / 2, g[k]},
                w[i] * w[j] * w[k] * (1 - g[j]) / 8);
      break;
    case CellType::tet4:
      for (std::size_t i = 0; i < m; ++i)
        for (std::size_t j = 0; j < m; ++j)
          for (std::size_t k = 0; k < m; ++k) {
            const double u = g[i], v = g[j], z = g[k];
            add({(1 + u) * (1 - v) * (1 - z) / 8, (1 + v) * (1 - z) / 4, (1 + z) / 2},
                w[i] * w[j] * w[k] * (1 - v) * (1 - z) * (1 - z) / 64);
          }
      break;
  }
  return rule;
}

double map_to_cell(CellType type, const double* x, const double* xi, double* point) {
  double n[8], dn[8][3];
  const int nodes = shape(type, xi, n, dn);
  const int dim = cell_dimension(type);
  double j[3][3] = {};
  for (int d = 0; d < dim; ++d) point[d] = 0.0;
  for (int a = 0; a < nodes; ++a)
    for (int d = 0; d < dim; ++d) {
      point[d] += n[a] * x[a * dim + d];
      for (int r = 0; r < dim; ++r) j[d][r] += x[a * dim + d] * dn[a][r];
    }
  if (dim == 2) return j[0][0] * j[1][1] - j[0][1] * j[1][0];
  return j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
         j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
}

double shape_gradients(CellType type, const double* x, const double* xi, double* grad) {
  double n[8], dn[8][3];
  const int nodes = shape(type, xi, n, dn);
  const int dim = cell_dimension(type);
  double j[3][3] = {};  // J_dr = dx_d / dxi_r; in 2D j[2][2] = 1, so the 3 x 3 inverse applies
  if (dim == 2) j[2][2] = 1.0;
  for (int a = 0; a < nodes; ++a)
    for (int d = 0; d < dim; ++d)
      for (int r = 0; r < dim; ++r) j[d][r] += x[a * dim + d] * dn[a][r];
  const double det = physics::determinant<3>(j);
  double inv[3][3];
  physics::inverse<3>(j, det, inv);
  // dN/dx_d = sum_r dN/dxi_r dxi_r/dx_d
  for (int a = 0; a < nodes; ++a)
    for (int d = 0; d < dim; ++d) {
      double g = 0;
      for (int r = 0; r < dim; ++r) g += dn[a][r] * inv[r][d];
      grad[a * dim + d] = g;
    }
  return det;
}

std::vector<double> reference_corners(CellType type) {
  switch (type) {
    case CellType::quad4:
      return {-1, -1, 1, -1, 1, 1, -1, 1};
    case CellType::tri3:
      return {0, 0, 1, 0, 0, 1};
    case CellType::hex8:
      return {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
    case CellType::tet4:
      return {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    case CellType::wedge6:
      return {0, 0, -1, 1, 0, -1, 0, 1, -1, 0, 0, 1, 1, 0, 1, 0, 1, 1};
  }
  throw std::logic_error("unknown cell type");
}

}  // namespace efg
