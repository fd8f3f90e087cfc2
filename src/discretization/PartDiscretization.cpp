#include "discretization/PartDiscretization.hpp"

#include <Teuchos_TimeMonitor.hpp>

#include "core/Errors.hpp"
#include "discretization/ShapeFunctions.hpp"

namespace efg {

PartDiscretization discretize_part(const BackgroundMesh& mesh, const PartSpec& part,
                                   const NodePartition& partition,
                                   const PressureCells* whole_groups) {
  PartDiscretization d;
  d.part = &part;
  const bool mixed = part.formulation == PartFormulation::mixed_up;
  if (mixed)
    d.pressure_cells =
        whole_groups ? groups_on_part(mesh, *whole_groups) : pressure_cells(mesh, part);
  {
    Teuchos::TimeMonitor timer(
        *Teuchos::TimeMonitor::getNewCounter("efg: neighbour search (ghosts, particles)"));
    d.ghosts = ghost_layer(
        mesh, partition.owner, partition.rank,
        ghost_radius(mesh, part, mixed ? largest_group_diameter(mesh, d.pressure_cells) : 0.0));
    d.cloud = make_particle_cloud(mesh, part, partition.owner, partition.rank, d.ghosts);
  }
  Teuchos::TimeMonitor timer(
      *Teuchos::TimeMonitor::getNewCounter("efg: shape functions and integration"));
  d.points = integrate_part(mesh, part, d.cloud, partition.owner, partition.rank);
  // Integration points that are not the particles' own (Gauss, SCNI subcells): the particles'
  // tables by direct evaluation (otherwise they are the points' tables).
  if (part.section.integration == Integration::gauss ||
      part.section.integration == Integration::scni_subcells) {
    const auto v = evaluate_shape_functions(
        d.cloud, d.cloud.position.data(), d.cloud.owned_count, true, [&](std::size_t p) {
          return "particle " +
                 std::to_string(mesh.global_node(static_cast<std::size_t>(d.cloud.mesh_node[p])) +
                                1);
        });
    d.own_particle_tables = true;
    d.own_particle_values = table_from(v, false, d.cloud.dimension);
    d.own_particle_gradients = table_from(v, true, d.cloud.dimension);
  }
  if (mixed)
    d.cells = cell_averages(mesh, d.cloud, d.pressure_cells,
                            owned_groups(mesh, d.pressure_cells, partition.owner, partition.rank));
  return d;
}

}  // namespace efg
