#include "model/DistributedMesh.hpp"

#include <malloc.h>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>

#include "core/Errors.hpp"
#include "discretization/ParticleCloud.hpp"
#include "io/ExodusSliceReader.hpp"
#include "mesh/GeneratedSlice.hpp"
#include "mesh/MeshValidation.hpp"
#include "model/GradedMaterials.hpp"
#include "model/SlicedRigidBlocks.hpp"
#include "model/SurfaceSliceChart.hpp"
#include "parallel/Collective.hpp"
#include "parallel/LocalMesh.hpp"
#include "parallel/SliceLookup.hpp"
#include "scene/SceneMeshChecks.hpp"
#include "scene/SceneNodeSets.hpp"
#include "scene/SchemaValidator.hpp"
#include "scene/ShellSurfacePoints.hpp"

namespace efg {

double halo_width(const Scene& scene, const std::vector<std::string>& block_names,
                  const std::vector<std::vector<double>>& extents, double group_diameter) {
  double halo = 0;
  for (const auto& part : scene.parts)
    for (std::size_t b = 0; b < block_names.size(); ++b) {
      if (std::find(part.blocks.begin(), part.blocks.end(), block_names[b]) == part.blocks.end())
        continue;
      // support_sizes (discretization/ParticleCloud.hpp): a_d = dilation_d h_d with h_d at most
      // the largest cell extent in d; a sphere takes dilation x max_d h_d.
      const auto& e = extents[b];
      const auto& dilation = part.section.dilation;
      auto dil = [&](std::size_t d) { return dilation.size() == 1 ? dilation[0] : dilation[d]; };
      double reach2 = 0, diameter2 = 0, largest = 0, largest_dilation = 0;
      for (std::size_t d = 0; d < e.size(); ++d) {
        reach2 += dil(d) * e[d] * dil(d) * e[d];
        diameter2 += e[d] * e[d];
        largest = std::max(largest, e[d]);
        largest_dilation = std::max(largest_dilation, dil(d));
      }
      const double reach = part.section.support == SupportShape::sphere ? largest_dilation * largest
                                                                        : std::sqrt(reach2);
      halo = std::max(halo, 2 * reach + std::max(std::sqrt(diameter2), group_diameter));
    }
  return halo * (1 + 1e-9);  // the ghost layer's own arithmetic may round the other way
}

BackgroundMesh load_distributed_mesh(const CommPtr& comm, Scene& scene, NodePartition& partition,
                                     SlicedPatches& patches) {
  // The key that named the mesh: messages about it point there.
  const auto key = scene.generator ? "generate" : "file";
  auto located = [&](const InputError& e) {
    return InputError(schema::located_message(scene.file, scene.document["mesh"][key],
                                              std::string("mesh.") + key, e.what()));
  };
  MeshSlice slice;
  run_collectively(comm, [&] {
    try {
      slice = scene.generator
                  ? generate_slice(*scene.generator, scene.more_blocks, comm->getRank(),
                                   comm->getSize())
                  : read_exodus_slice(scene.mesh_file, comm->getRank(), comm->getSize());
    } catch (const InputError& e) {
      throw located(e);
    }
  });
  // Rigid bodies of mesh blocks: out of the slices, as the root path takes them out of the mesh.
  take_rigid_blocks_from_slices(comm, scene, slice);
  // A shell surface read in 3D: charted in its slices, the halo sized in the chart.
  std::vector<double> positions;
  SurfaceProjection plane;
  const auto nodes = slice.node_count;
  const bool surface = is_surface_slice(scene, slice);  // the same on every rank
  if (surface) try {
      positions = chart_surface_slice(comm, scene, slice, plane);
    } catch (const InputError& e) {
      throw located(e);  // a cell the projection cannot chart, named by this rank
    }
  else if (scene.surface_chart)
    refuse_chart_without_surface(scene);
  // Pressure patches are chosen over the whole part, before the halo is sized by them.
  patches = patches_from_slices(comm, scene, slice);
  std::vector<std::string> names;
  for (const auto& b : slice.blocks) names.push_back(b.name);
  auto local = distribute_mesh(comm, slice, [&](const BlockExtents& extents) {
    return halo_width(scene, names, extents, patches.largest_diameter);
  });
  slice = MeshSlice();  // the slice has served: free it before the discretization
  auto& mesh = local.mesh;
  if (surface) {
    mesh.surface = fetch_from_slices(comm, nodes, 3, positions, mesh.global.nodes);
    mesh.chart_plane = plane;
    chart_shell_points(scene, mesh);
  }
  run_collectively(comm, [&] {
    try {
      validate_mesh(mesh);
    } catch (const InputError& e) {
      throw located(e);
    }
  });
  partition.rank = comm->getRank();
  partition.size = comm->getSize();
  partition.owner = std::move(local.owner);
  partition.owned.clear();
  for (std::size_t n = 0; n < partition.owner.size(); ++n)
    if (partition.owner[n] == partition.rank) partition.owned.push_back(static_cast<LocalIndex>(n));
  // a box may hold none of this part's nodes, but some rank's
  add_scene_node_sets(scene, mesh, [&](bool held) {
    int mine = held ? 1 : 0, any = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(any));
    return any > 0;
  });
  run_collectively(comm, [&] {
    check_scene_against_mesh(scene, mesh, MeshOwners{comm, &partition.owner, partition.rank});
  });
  // Per-part supports take the part's largest half-widths over the whole mesh: each node's are
  // right on its owner (all its cells are there), so the largest over the owned nodes, over the
  // ranks.
  for (auto& part : scene.parts) {
    if (!part.section.per_part_support) continue;
    auto section = part.section;
    section.per_part_support = false;
    const auto a = support_sizes(mesh, part.blocks, section);
    const auto dim = static_cast<std::size_t>(mesh.dimension);
    std::vector<double> mine(dim, 0.0), largest(dim, 0.0);
    for (auto n : partition.owned)
      for (std::size_t d = 0; d < dim; ++d)
        mine[d] = std::max(mine[d], a[static_cast<std::size_t>(n) * dim + d]);
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(dim), mine.data(),
                       largest.data());
    part.section.part_support = largest;
  }
  // A graded modulus' reference is its largest value over the whole mesh.
  set_graded_references(scene, mesh);
  for (auto& m : scene.materials) {
    if (!m.youngs_modulus_field) continue;
    double mine = m.constants["youngs_modulus"], largest = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(largest));
    m.constants["youngs_modulus"] = largest;
  }
  // The read's exchanges allocated and freed several times the part (lists packed and
  // received); glibc keeps freed heap for reuse, so hand it back: the memory account then shows
  // what the part keeps.
  malloc_trim(0);
  return std::move(mesh);
}

}  // namespace efg
