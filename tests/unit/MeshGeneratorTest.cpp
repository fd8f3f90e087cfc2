#include <gtest/gtest.h>

#include <cmath>

#include <numeric>

#include "core/Errors.hpp"
#include "mesh/MeshValidation.hpp"
#include "mesh/NodalVolume.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

struct Expected {
  CellType type;
  int cells_per_hex;
};

class GeneratorByElement : public ::testing::TestWithParam<Expected> {};

TEST_P(GeneratorByElement, CountsVolumesAndSets) {
  const auto [type, per_cube] = GetParam();
  for (double perturbation : {0.0, 0.3}) {
    const auto spec = test::box_spec(type, 3, perturbation);
    const auto mesh = generate_mesh(spec);
    EXPECT_NO_THROW(validate_mesh(mesh));
    const bool is3d = mesh.dimension == 3;
    const std::size_t nx = 7, ny = 4, nz = is3d ? 4 : 1;
    EXPECT_EQ(mesh.node_count(), nx * ny * nz);
    EXPECT_EQ(mesh.cell_count(), static_cast<std::size_t>(6 * 3 * (is3d ? 3 : 1) * per_cube));
    // Cells tile the domain exactly: their volumes add up to the box's, perturbed or not.
    const auto volumes = lumped_nodal_volumes(mesh);
    const double total = std::accumulate(volumes.begin(), volumes.end(), 0.0);
    EXPECT_NEAR(total, 2.0, 1e-13) << cell_scene_name(type) << " perturbation " << perturbation;
    for (double v : volumes) EXPECT_GT(v, 0.0);
    // Boundary sets: nodes and sides on each plane.
    ASSERT_NE(mesh.find_node_set("xmin"), nullptr);
    EXPECT_EQ(mesh.find_node_set("xmin")->nodes.size(), ny * nz);
    EXPECT_EQ(mesh.find_node_set("ymax")->nodes.size(), nx * nz);
    EXPECT_EQ(mesh.find_node_set("all")->nodes.size(), mesh.node_count());
    for (const auto& set : mesh.side_sets) {
      // Side areas on a plane add up to the plane's area; every side node lies on the plane.
      double area = 0;
      for (std::size_t i = 0; i < set.cells.size(); ++i) {
        const auto nodes =
            mesh.side_node_indices(static_cast<std::size_t>(set.cells[i]), set.sides[i]);
        std::vector<double> x;
        for (auto n : nodes)
          for (int d = 0; d < mesh.dimension; ++d)
            x.push_back(mesh.coordinates[static_cast<std::size_t>(n) *
                                             static_cast<std::size_t>(mesh.dimension) +
                                         static_cast<std::size_t>(d)]);
        if (!is3d) {
          area += std::hypot(x[2] - x[0], x[3] - x[1]);
        } else {
          const auto tri = [&](int a, int b, int c) {
            const double u[3] = {x[3 * b] - x[3 * a], x[3 * b + 1] - x[3 * a + 1],
                                 x[3 * b + 2] - x[3 * a + 2]};
            const double v[3] = {x[3 * c] - x[3 * a], x[3 * c + 1] - x[3 * a + 1],
                                 x[3 * c + 2] - x[3 * a + 2]};
            return 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) +
                                   std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                                   std::pow(u[0] * v[1] - u[1] * v[0], 2));
          };
          area += tri(0, 1, 2) + (nodes.size() == 4 ? tri(0, 2, 3) : 0.0);
        }
      }
      // Domain [0,2]x[0,1](x[0,1]): the x planes measure 1, the others 2 (length or area).
      const double expected_area = set.name[0] == 'x' ? 1.0 : 2.0;
      EXPECT_NEAR(area, expected_area, 1e-12) << set.name << " " << cell_scene_name(type);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllElements, GeneratorByElement,
                         ::testing::Values(Expected{CellType::quad4, 1},
                                           Expected{CellType::tri3, 2}, Expected{CellType::hex8, 1},
                                           Expected{CellType::tet4, 6},
                                           Expected{CellType::wedge6, 2}),
                         [](const auto& p) { return cell_scene_name(p.param.type); });

TEST(MeshGenerator, PerturbationIsSeededAndKeepsBoundaryPlanes) {
  const auto a = generate_mesh(test::box_spec(CellType::hex8, 4, 0.3, 11));
  const auto b = generate_mesh(test::box_spec(CellType::hex8, 4, 0.3, 11));
  const auto c = generate_mesh(test::box_spec(CellType::hex8, 4, 0.3, 12));
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_NE(a.coordinates, c.coordinates);
  for (auto n : a.find_node_set("xmax")->nodes)
    EXPECT_EQ(a.coordinates[3 * static_cast<std::size_t>(n)], 2.0);
  // Interior nodes moved by at most 30 % of the spacing (0.25) per direction.
  const auto regular = generate_mesh(test::box_spec(CellType::hex8, 4));
  double largest = 0, smallest = 1;
  for (std::size_t i = 0; i < a.coordinates.size(); ++i) {
    const double shift = std::abs(a.coordinates[i] - regular.coordinates[i]);
    largest = std::max(largest, shift);
    if (shift > 0) smallest = std::min(smallest, shift);
  }
  EXPECT_LE(largest, 0.3 * 0.25 + 1e-15);
  EXPECT_GT(largest, 0.2 * 0.25);  // the perturbation really happened
}

TEST(MeshGenerator, RejectsMismatchedElementAndDimension) {
  auto spec = test::box_spec(CellType::hex8, 2);
  spec.dimension = 2;
  EXPECT_THROW(generate_mesh(spec), InputError);
}

}  // namespace
}  // namespace efg
