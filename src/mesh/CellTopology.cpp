#include "mesh/CellTopology.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace efg {
namespace {

// Exodus side tables, 1-based in the Exodus manual, 0-based here.
const std::vector<std::vector<int>> kQuad4Sides = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const std::vector<std::vector<int>> kTri3Sides = {{0, 1}, {1, 2}, {2, 0}};
const std::vector<std::vector<int>> kHex8Sides = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                  {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
const std::vector<std::vector<int>> kTet4Sides = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
const std::vector<std::vector<int>> kWedge6Sides = {
    {0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};

const std::vector<std::vector<int>>& side_table(CellType type) {
  switch (type) {
    case CellType::quad4: return kQuad4Sides;
    case CellType::tri3: return kTri3Sides;
    case CellType::hex8: return kHex8Sides;
    case CellType::tet4: return kTet4Sides;
    case CellType::wedge6: return kWedge6Sides;
  }
  throw std::logic_error("unknown cell type");
}

double det2(const double j[2][2]) { return j[0][0] * j[1][1] - j[0][1] * j[1][0]; }

double det3(const double j[3][3]) {
  return j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1]) -
         j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0]) +
         j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
}

// Jacobian determinant of an isoparametric cell at a reference point, from the shape function
// derivatives dN[node][ref_dir].
template <int Dim, int Nodes>
double jacobian_det(const double* x, const double (&dN)[Nodes][Dim]) {
  double j[Dim][Dim] = {};
  for (int a = 0; a < Nodes; ++a)
    for (int i = 0; i < Dim; ++i)
      for (int r = 0; r < Dim; ++r) j[i][r] += x[a * Dim + i] * dN[a][r];
  if constexpr (Dim == 2) {
    return det2(j);
  } else {
    return det3(j);
  }
}

void quad4_derivatives(double r, double s, double (&dN)[4][2]) {
  const double rs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int a = 0; a < 4; ++a) {
    dN[a][0] = 0.25 * rs[a][0] * (1 + rs[a][1] * s);
    dN[a][1] = 0.25 * rs[a][1] * (1 + rs[a][0] * r);
  }
}

void hex8_derivatives(double r, double s, double t, double (&dN)[8][3]) {
  const double c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a) {
    dN[a][0] = 0.125 * c[a][0] * (1 + c[a][1] * s) * (1 + c[a][2] * t);
    dN[a][1] = 0.125 * c[a][1] * (1 + c[a][0] * r) * (1 + c[a][2] * t);
    dN[a][2] = 0.125 * c[a][2] * (1 + c[a][0] * r) * (1 + c[a][1] * s);
  }
}

// Wedge: N = L_i(r, s) (1 -/+ t) / 2 with L = (1 - r - s, r, s), t in [-1, 1].
void wedge6_derivatives(double r, double s, double t, double (&dN)[6][3]) {
  const double l[3] = {1 - r - s, r, s};
  const double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int layer = 0; layer < 2; ++layer) {
    const double h = layer == 0 ? 0.5 * (1 - t) : 0.5 * (1 + t);
    const double dh = layer == 0 ? -0.5 : 0.5;
    for (int i = 0; i < 3; ++i) {
      const int a = 3 * layer + i;
      dN[a][0] = dl[i][0] * h;
      dN[a][1] = dl[i][1] * h;
      dN[a][2] = l[i] * dh;
    }
  }
}

const double kGauss2 = 1.0 / std::sqrt(3.0);

}  // namespace

int cell_dimension(CellType type) {
  return (type == CellType::quad4 || type == CellType::tri3) ? 2 : 3;
}

int cell_node_count(CellType type) {
  switch (type) {
    case CellType::quad4: return 4;
    case CellType::tri3: return 3;
    case CellType::hex8: return 8;
    case CellType::tet4: return 4;
    case CellType::wedge6: return 6;
  }
  throw std::logic_error("unknown cell type");
}

int cell_side_count(CellType type) { return static_cast<int>(side_table(type).size()); }

std::vector<int> cell_side_nodes(CellType type, int side) {
  const auto& table = side_table(type);
  if (side < 0 || side >= static_cast<int>(table.size()))
    throw std::out_of_range("side index out of range for " + cell_scene_name(type));
  return table[static_cast<std::size_t>(side)];
}

std::string cell_exodus_name(CellType type) {
  switch (type) {
    case CellType::quad4: return "QUAD4";
    case CellType::tri3: return "TRI3";
    case CellType::hex8: return "HEX8";
    case CellType::tet4: return "TETRA4";
    case CellType::wedge6: return "WEDGE6";
  }
  throw std::logic_error("unknown cell type");
}

std::string cell_scene_name(CellType type) {
  switch (type) {
    case CellType::quad4: return "quad4";
    case CellType::tri3: return "tri3";
    case CellType::hex8: return "hex8";
    case CellType::tet4: return "tet4";
    case CellType::wedge6: return "wedge6";
  }
  throw std::logic_error("unknown cell type");
}

std::optional<CellType> cell_type_from_exodus_name(const std::string& name) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (n == "QUAD" || n == "QUAD4") return CellType::quad4;
  if (n == "TRI" || n == "TRI3" || n == "TRIANGLE") return CellType::tri3;
  if (n == "HEX" || n == "HEX8") return CellType::hex8;
  if (n == "TET" || n == "TET4" || n == "TETRA" || n == "TETRA4") return CellType::tet4;
  if (n == "WEDGE" || n == "WEDGE6") return CellType::wedge6;
  return std::nullopt;
}

CellGeometry cell_geometry(CellType type, const double* x) {
  CellGeometry g;
  g.min_corner_det = std::numeric_limits<double>::max();
  switch (type) {
    case CellType::tri3: {
      const double d = (x[2] - x[0]) * (x[5] - x[1]) - (x[4] - x[0]) * (x[3] - x[1]);
      g.volume = 0.5 * d;
      g.min_corner_det = d;
      break;
    }
    case CellType::tet4: {
      const double j[3][3] = {{x[3] - x[0], x[6] - x[0], x[9] - x[0]},
                              {x[4] - x[1], x[7] - x[1], x[10] - x[1]},
                              {x[5] - x[2], x[8] - x[2], x[11] - x[2]}};
      const double d = det3(j);
      g.volume = d / 6.0;
      g.min_corner_det = d;
      break;
    }
    case CellType::quad4: {
      double dN[4][2];
      // det J of a bilinear map is linear in each variable: 2x2 Gauss is exact.
      for (double r : {-kGauss2, kGauss2})
        for (double s : {-kGauss2, kGauss2}) {
          quad4_derivatives(r, s, dN);
          g.volume += jacobian_det<2, 4>(x, dN);
        }
      for (double r : {-1.0, 1.0})
        for (double s : {-1.0, 1.0}) {
          quad4_derivatives(r, s, dN);
          g.min_corner_det = std::min(g.min_corner_det, jacobian_det<2, 4>(x, dN));
        }
      break;
    }
    case CellType::hex8: {
      double dN[8][3];
      // det J of a trilinear map is quadratic in each variable: 2x2x2 Gauss is exact.
      for (double r : {-kGauss2, kGauss2})
        for (double s : {-kGauss2, kGauss2})
          for (double t : {-kGauss2, kGauss2}) {
            hex8_derivatives(r, s, t, dN);
            g.volume += jacobian_det<3, 8>(x, dN);
          }
      for (double r : {-1.0, 1.0})
        for (double s : {-1.0, 1.0})
          for (double t : {-1.0, 1.0}) {
            hex8_derivatives(r, s, t, dN);
            g.min_corner_det = std::min(g.min_corner_det, jacobian_det<3, 8>(x, dN));
          }
      break;
    }
    case CellType::wedge6: {
      double dN[6][3];
      // det J is linear in (r, s) and quadratic in t: 3-point triangle rule x 2-point Gauss.
      const double tri[3][2] = {{1.0 / 6, 1.0 / 6}, {2.0 / 3, 1.0 / 6}, {1.0 / 6, 2.0 / 3}};
      for (const auto& p : tri)
        for (double t : {-kGauss2, kGauss2}) {
          wedge6_derivatives(p[0], p[1], t, dN);
          g.volume += jacobian_det<3, 6>(x, dN) / 6.0;
        }
      const double corners[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      for (const auto& p : corners)
        for (double t : {-1.0, 1.0}) {
          wedge6_derivatives(p[0], p[1], t, dN);
          g.min_corner_det = std::min(g.min_corner_det, jacobian_det<3, 6>(x, dN));
        }
      break;
    }
  }
  return g;
}

}  // namespace efg
