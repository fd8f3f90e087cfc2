// One meshfree part, discretized on this rank: its particle cloud (owned + ghosts) and the
// integration points of the owned part of the domain.
#pragma once

#include <vector>

#include "discretization/CellSmoothing.hpp"
#include "discretization/IntegrationPoints.hpp"
#include "parallel/NodePartition.hpp"

namespace efg {

struct PartDiscretization {
  const PartSpec* part = nullptr;
  std::vector<LocalIndex> ghosts;  ///< mesh nodes of other ranks this rank needs, ascending
  ParticleCloud cloud;
  IntegrationPoints points;
  /// Shape functions and gradients at the owned particles (rows in cloud order): physical
  /// displacements u(X_J) = sum_I phi_I(X_J) d_I for output and essential conditions, and the
  /// gradients output strains come from (SCNI: the smoothed ones; Gauss: direct). Where the
  /// particles are the integration points (SCNI, direct nodal) these are the points' own tables,
  /// not a copy of them (issue 20: about 1 KB per particle at dilation 1.2 in 3D).
  const CsrTable& particle_values() const {
    return own_particle_tables ? own_particle_values : points.values;
  }
  const CsrTable& particle_gradients() const {
    return own_particle_tables ? own_particle_gradients : points.gradients;
  }
  /// Gauss cells and SCNI subcells: the particles' tables by direct evaluation.
  bool own_particle_tables = false;
  CsrTable own_particle_values, own_particle_gradients;
  /// formulation mixed_up: the part's pressure cells (every group, on every rank) and the
  /// averaged gradients of the owned ones; empty otherwise (a displacement part builds no
  /// pressure data).
  PressureCells pressure_cells;
  CellAverages cells;
};

/// Ghost layer from the part's support reach and cell size, particle cloud, integration points.
/// `whole_groups`: a mixed u-p part's pressure groups chosen over the whole mesh (whole-mesh cell
/// indices) when `mesh` is a rank's part of it (discretization/PressureCells, groups_on_part);
/// null: chosen here.
PartDiscretization discretize_part(const BackgroundMesh& mesh, const PartSpec& part,
                                   const NodePartition& partition,
                                   const PressureCells* whole_groups = nullptr);

}  // namespace efg
