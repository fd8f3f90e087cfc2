// Points whose moment matrix cannot be inverted are reported, never passed on as NaN.
#include <gtest/gtest.h>

#include "core/Errors.hpp"
#include "discretization/IntegrationPoints.hpp"
#include "discretization/ShapeFunctions.hpp"
#include "support/Clouds.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

std::string error_of(const ParticleCloud& cloud, const std::vector<double>& points) {
  try {
    evaluate_shape_functions(cloud, points.data(),
                             points.size() / static_cast<std::size_t>(cloud.dimension), true);
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeFunctionDiagnostics, DilationTooSmall) {
  // Dilation 1.0: at a node only the node's own support reaches (neighbours sit exactly on the
  // support's edge, where the kernel vanishes).
  SectionSpec section;
  section.dilation = {1.0};
  const auto cloud = test::mesh_cloud(generate_mesh(test::box_spec(CellType::quad4, 4)), section);
  const auto message = error_of(cloud, {0.5, 0.5});
  EXPECT_NE(message.find("shape functions: evaluation point 0 at (0.5, 0.5)"), std::string::npos)
      << message;
  EXPECT_NE(
      message.find("only 1 particle support(s) cover it, a linear basis in 2D needs at least 3"),
      std::string::npos)
      << message;
  EXPECT_NE(message.find("increase the part's dilation (now 1)"), std::string::npos) << message;
}

TEST(ShapeFunctionDiagnostics, AllNeighboursOnALine) {
  // Five particles on the line y = x: enough of them, but a 2D linear basis is singular.
  ParticleCloud cloud;
  cloud.dimension = 2;
  cloud.section.dilation = {3.0};
  for (int i = 0; i < 5; ++i) {
    cloud.mesh_node.push_back(i);
    cloud.position.insert(cloud.position.end(), {0.25 * i, 0.25 * i});
    cloud.support.insert(cloud.support.end(), {1.0, 1.0});
    cloud.volume.push_back(1.0);
  }
  cloud.owned_count = cloud.size();
  const auto message = error_of(cloud, {0.4, 0.5});
  EXPECT_NE(message.find("the moment matrix is singular with 5 neighbours (at least 3 needed, not "
                         "all on one line or plane)"),
            std::string::npos)
      << message;
}

TEST(ShapeFunctionDiagnostics, NodalIntegrationNamesTheParticle) {
  BackgroundMesh mesh = generate_mesh(test::box_spec(CellType::hex8, 2));
  PartSpec part;
  part.blocks = {"block_1"};
  part.section.dilation = {1.0};
  part.section.integration = Integration::nodal;
  const std::vector<int> owner(mesh.node_count(), 0);
  const auto cloud = make_particle_cloud(mesh, part, owner, 0, {});
  try {
    integrate_part(mesh, part, cloud, owner, 0);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("nodal integration point at particle 1 at (0, 0, 0)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace efg
