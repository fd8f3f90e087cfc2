// The folded-material guard (operators/CellInversion, issue 56, item 5) on 1, 2 and 3 ranks:
// background cells carried by prescribed displacement fields of known geometry.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <Tpetra_Import.hpp>

#include <cmath>
#include <functional>
#include <set>

#include "operators/CellInversion.hpp"
#include "scene/SceneReader.hpp"

namespace efg {
namespace {

// A 4 x 4 unit square of quad4 cells (h = 0.25): nodes x-fastest (node (i, j) = 5 j + i), cells
// likewise (cell (i, j) = 4 j + i).
Model square() {
  return build_model(Tpetra::getDefaultComm(), parse_scene(R"(
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [1, 1], cells: [4, 4]}
parts:
  - {name: sheet, blocks: [block_1], material: m, plane: strain}
materials:
  - {name: m, model: linear_elastic, youngs_modulus: 100, poissons_ratio: 0.3}
)",
                                                           "cells.yaml"));
}

// The overlap displacements u(node, X) (2 components) of every overlap particle.
Tpetra::Vector<> displaced(
    const Model& model, const std::function<std::array<double, 2>(long long, double, double)>& u) {
  Tpetra::Vector<> owned(model.maps.owned_dofs), overlap(model.maps.overlap_dofs);
  const auto& map = *model.maps.owned_dofs;
  auto v = owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) {
    const auto dof = map.getGlobalElement(static_cast<int>(k));
    const long long node = dof / 2;
    const auto local = static_cast<std::size_t>(model.mesh.node_of(node));
    const double x = model.mesh.coordinates[2 * local], y = model.mesh.coordinates[2 * local + 1];
    v(k, 0) = u(node, x, y)[static_cast<std::size_t>(dof % 2)];
  }
  overlap.doImport(owned, Tpetra::Import<>(model.maps.owned_dofs, model.maps.overlap_dofs),
                   Tpetra::INSERT);
  return overlap;
}

TEST(CellInversion, RigidMotionsAndSmallStrainsKeepEveryCell) {
  const auto model = square();
  const CellInversion cells(model);
  // at rest; turned by 180 degrees (a proper rotation, however large); stretched 3x and sheared
  for (const auto& u : std::vector<std::function<std::array<double, 2>(long long, double, double)>>{
           [](long long, double, double) {
             return std::array<double, 2>{0, 0};
           },
           [](long long, double x, double y) {
             return std::array<double, 2>{-2 * x, -2 * y};
           },
           [](long long, double x, double y) {
             return std::array<double, 2>{2 * x + y, 0.5 * x};
           }})
    EXPECT_FALSE(cells.most_inverted(displaced(model, u)));
}

TEST(CellInversion, AMirroredSheetTurnsEveryCellInsideOut) {
  const auto model = square();
  const CellInversion cells(model);
  // x -> -x: every corner Jacobian changes sign (ratio -1 everywhere): the first cell, cell 1.
  const auto folded = cells.most_inverted(displaced(model, [](long long, double x, double) {
    return std::array<double, 2>{-2 * x, 0};
  }));
  ASSERT_TRUE(folded);
  EXPECT_EQ(folded->cell, 1);
  EXPECT_EQ(folded->part, "sheet");
  // The corner Jacobian of the bilinear map of an h x h square is (h / 2)^2 = 1/64, mirrored -1/64.
  EXPECT_NEAR(folded->reference_det, 1.0 / 64, 1e-15);
  EXPECT_NEAR(folded->current_det, -1.0 / 64, 1e-15);
  EXPECT_TRUE(std::set<long long>({1, 2, 6, 7}).count(folded->particle)) << folded->particle;
}

TEST(CellInversion, AParticlePushedPastItsDiagonalNeighbourIsNamed) {
  const auto model = square();
  const CellInversion cells(model);
  // Node (1, 1) (0-based 6) moved by (d, d): at d = 0.4 h its four cells stay convex; at 1.5 h it
  // lies beyond node (2, 2). Corner Jacobians of a bilinear quad: the cross product of the two
  // edges leaving the corner over 4; in units of h: cells (1, 0) and (0, 1) get a reflex corner
  // at (2, 1) and (1, 2) (cross -0.5, ratio -0.5 to the square's 1); cell (1, 1) (1-based 6:
  // nodes (1,1) -> (2.5, 2.5), (2,1), (2,2), (1,2)) turns over at the moved node itself:
  // (-0.5, -1.5) x (-1.5, -0.5) = -2, ratio -2: the most inverted, named at particle 7.
  const auto push = [&](double d) {
    return displaced(model, [d](long long node, double, double) {
      return node == 6 ? std::array<double, 2>{d, d} : std::array<double, 2>{0, 0};
    });
  };
  EXPECT_FALSE(cells.most_inverted(push(0.4 * 0.25)));
  const auto folded = cells.most_inverted(push(1.5 * 0.25));
  ASSERT_TRUE(folded);
  EXPECT_EQ(folded->cell, 6);
  EXPECT_EQ(folded->particle, 7);
  EXPECT_NEAR(folded->current_det, -2.0 / 64, 1e-15);
  EXPECT_NEAR(folded->ratio(), -2.0, 1e-12);
}

}  // namespace
}  // namespace efg
