// The discretization of the owned part of the domain, built from owned + ghost particles only,
// equals the one built with every particle available: the ghost layer is complete and sums run
// in the same order on any number of ranks.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <cmath>

#include "discretization/PartDiscretization.hpp"
#include "support/TestMeshes.hpp"

namespace efg {
namespace {

void expect_identical(const CsrTable& a, const ParticleCloud& ca, const CsrTable& b,
                      const ParticleCloud& cb, double& worst) {
  ASSERT_EQ(a.rows(), b.rows());
  for (std::size_t r = 0; r < a.rows(); ++r) {
    ASSERT_EQ(a.offsets[r + 1] - a.offsets[r], b.offsets[r + 1] - b.offsets[r]) << "row " << r;
    for (auto k = a.offsets[r], m = b.offsets[r]; k < a.offsets[r + 1]; ++k, ++m) {
      ASSERT_EQ(ca.mesh_node[static_cast<std::size_t>(a.particles[k])],
                cb.mesh_node[static_cast<std::size_t>(b.particles[m])]);
      for (int w = 0; w < a.width; ++w) {
        const auto i = k * static_cast<std::size_t>(a.width) + static_cast<std::size_t>(w);
        const auto j = m * static_cast<std::size_t>(a.width) + static_cast<std::size_t>(w);
        worst = std::max(worst, std::abs(a.values[i] - b.values[j]));
      }
    }
  }
}

TEST(Discretization, GhostLayerGivesTheSameOperatorsAsAllParticles) {
  const auto comm = Tpetra::getDefaultComm();
  for (auto type : {CellType::quad4, CellType::hex8, CellType::tet4}) {
    for (auto scheme : {Integration::scni, Integration::nodal, Integration::gauss}) {
      const auto mesh =
          generate_mesh(test::box_spec(type, cell_dimension(type) == 2 ? 10 : 6, 0.3, 5));
      PartSpec part;
      part.name = "part";
      part.blocks = {"block_1"};
      part.section.integration = scheme;
      part.section.dilation = {1.7};
      const auto partition = partition_nodes(comm, mesh);
      const auto d = discretize_part(mesh, part, partition);
      std::vector<LocalIndex> everyone(mesh.node_count());
      for (std::size_t n = 0; n < everyone.size(); ++n) everyone[n] = static_cast<LocalIndex>(n);
      const auto full = make_particle_cloud(mesh, part, partition.owner, partition.rank, everyone);
      const auto reference = integrate_part(mesh, part, full, partition.owner, partition.rank);
      ASSERT_EQ(d.points.weight, reference.weight);
      ASSERT_EQ(d.points.x, reference.x);
      double worst = 0;
      expect_identical(d.points.values, d.cloud, reference.values, full, worst);
      expect_identical(d.points.gradients, d.cloud, reference.gradients, full, worst);
      EXPECT_LE(worst, 1e-13) << cell_scene_name(type) << " scheme " << static_cast<int>(scheme);
      if (comm->getSize() == 2 && type == CellType::quad4) {
        EXPECT_LT(d.cloud.size(),
                  full.size());  // 2 halves of the 2D mesh: the ghosts are a strict subset
      }
      double mine = 0, total = 0;
      for (double w : d.points.weight) mine += w;
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(total));
      EXPECT_NEAR(total, 2.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace efg
