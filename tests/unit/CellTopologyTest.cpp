#include <gtest/gtest.h>

#include <cmath>

#include "mesh/CellTopology.hpp"

namespace efg {
namespace {

// Unit reference cells in Exodus node order.
const double kQuad[] = {0, 0, 1, 0, 1, 1, 0, 1};
const double kTri[] = {0, 0, 1, 0, 0, 1};
const double kHex[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
const double kTet[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const double kWedge[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1};

TEST(CellTopology, ReferenceVolumes) {
  EXPECT_DOUBLE_EQ(cell_geometry(CellType::quad4, kQuad).volume, 1.0);
  EXPECT_DOUBLE_EQ(cell_geometry(CellType::tri3, kTri).volume, 0.5);
  EXPECT_DOUBLE_EQ(cell_geometry(CellType::hex8, kHex).volume, 1.0);
  EXPECT_DOUBLE_EQ(cell_geometry(CellType::tet4, kTet).volume, 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(cell_geometry(CellType::wedge6, kWedge).volume, 0.5);
}

TEST(CellTopology, DistortedHexVolumeIsExact) {
  // Move one corner so that three faces are warped; 2x2x2 Gauss must still integrate det J
  // exactly (it is quadratic in each variable). Reference: a 40^3 midpoint rule of det J,
  // whose error is about h^2/24 relative.
  double x[24];
  std::copy(std::begin(kHex), std::end(kHex), x);
  x[18] = 1.5, x[19] = 1.3, x[20] = 1.2;
  const double v = cell_geometry(CellType::hex8, x).volume;
  const int n = 40;
  double reference = 0;
  const double c[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double r = -1 + (2.0 * i + 1) / n, s = -1 + (2.0 * j + 1) / n,
                     t = -1 + (2.0 * k + 1) / n;
        double jm[3][3] = {};
        for (int a = 0; a < 8; ++a) {
          const double d[3] = {0.125 * c[a][0] * (1 + c[a][1] * s) * (1 + c[a][2] * t),
                               0.125 * c[a][1] * (1 + c[a][0] * r) * (1 + c[a][2] * t),
                               0.125 * c[a][2] * (1 + c[a][0] * r) * (1 + c[a][1] * s)};
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q) jm[p][q] += x[3 * a + p] * d[q];
        }
        const double det = jm[0][0] * (jm[1][1] * jm[2][2] - jm[1][2] * jm[2][1]) -
                           jm[0][1] * (jm[1][0] * jm[2][2] - jm[1][2] * jm[2][0]) +
                           jm[0][2] * (jm[1][0] * jm[2][1] - jm[1][1] * jm[2][0]);
        reference += det * std::pow(2.0 / n, 3);
      }
  EXPECT_NEAR(v, reference, 2e-4 * reference);
}

TEST(CellTopology, InvertedCellsHaveNegativeCornerJacobian) {
  const double flipped[] = {0, 0, 0, 1, 1, 0};  // tri3 clockwise
  EXPECT_LT(cell_geometry(CellType::tri3, flipped).min_corner_det, 0);
  double hex[24];
  std::copy(std::begin(kHex), std::end(kHex), hex);
  hex[20] = -0.5;  // node 7 pushed below the bottom face
  EXPECT_LT(cell_geometry(CellType::hex8, hex).min_corner_det, 0);
}

// Sides must be oriented outward: the divergence theorem sum over sides of (area vector) = 0 and
// sum of x . n dA / dim = volume.
double flux_of_position(CellType type, const double* x) {
  const int dim = cell_dimension(type);
  double flux = 0;
  for (int s = 0; s < cell_side_count(type); ++s) {
    const auto nodes = cell_side_nodes(type, s);
    if (dim == 2) {
      const double* a = x + 2 * nodes[0];
      const double* b = x + 2 * nodes[1];
      const double n[2] = {b[1] - a[1], -(b[0] - a[0])};  // outward for counter-clockwise cells
      flux += 0.5 * ((a[0] + b[0]) * n[0] + (a[1] + b[1]) * n[1]);
    } else {
      // Fan triangulation from the side's first node; exact for planar sides.
      for (std::size_t k = 1; k + 1 < nodes.size(); ++k) {
        const double* p = x + 3 * nodes[0];
        const double* q = x + 3 * nodes[k];
        const double* r = x + 3 * nodes[k + 1];
        const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
        const double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        const double n[3] = {0.5 * (u[1] * v[2] - u[2] * v[1]), 0.5 * (u[2] * v[0] - u[0] * v[2]),
                             0.5 * (u[0] * v[1] - u[1] * v[0])};
        for (int d = 0; d < 3; ++d) flux += (p[d] + q[d] + r[d]) / 3.0 * n[d];
      }
    }
  }
  return flux / dim;
}

TEST(CellTopology, SidesPointOutward) {
  EXPECT_NEAR(flux_of_position(CellType::quad4, kQuad), 1.0, 1e-14);
  EXPECT_NEAR(flux_of_position(CellType::tri3, kTri), 0.5, 1e-14);
  EXPECT_NEAR(flux_of_position(CellType::hex8, kHex), 1.0, 1e-14);
  EXPECT_NEAR(flux_of_position(CellType::tet4, kTet), 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(flux_of_position(CellType::wedge6, kWedge), 0.5, 1e-14);
}

TEST(CellTopology, ExodusNames) {
  for (auto t : {CellType::quad4, CellType::tri3, CellType::hex8, CellType::tet4, CellType::wedge6})
    EXPECT_EQ(cell_type_from_exodus_name(cell_exodus_name(t)), t);
  EXPECT_EQ(cell_type_from_exodus_name("hex"), CellType::hex8);
  // shell cells are the surface cells of a 3D shell mesh (mesh/SurfaceChart.hpp)
  EXPECT_EQ(cell_type_from_exodus_name("SHELL4"), CellType::quad4);
  EXPECT_EQ(cell_type_from_exodus_name("TRISHELL3"), CellType::tri3);
  EXPECT_FALSE(cell_type_from_exodus_name("SHELL8").has_value());
  EXPECT_FALSE(cell_type_from_exodus_name("HEX20").has_value());
}

}  // namespace
}  // namespace efg
