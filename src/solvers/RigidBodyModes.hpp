// The rigid-body modes of a displacement field discretized by particles: the near-null space of
// the elasticity operator that smoothed-aggregation multigrid must reproduce on every level
// (Vanek, Mandel & Brezina 1996). With shape functions of (at least) linear consistency,
// sum_I phi_I(x) (a + W X_I) = a + W x, so the generalized values d_I = a + W X_I of a
// translation a or an infinitesimal rotation W (skew) give exactly that rigid motion: the modes
// are built from particle coordinates alone, even though the shape functions do not interpolate.
#pragma once

#include <Tpetra_MultiVector.hpp>

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "parallel/DofMaps.hpp"

namespace efg {

/// Columns: dim translations, then the rotations (1 in 2D about z; 3 in 3D about x, y, z), all
/// about the centroid of the mesh's nodes so that the columns are well scaled (the same centre on
/// every rank: of the whole mesh, or summed over the ranks' owned nodes for a rank's part of a
/// mesh read in slices). The owned particles are looked up in `mesh` by their global id in
/// maps.owned_nodes; dof = node * dim + component.
Teuchos::RCP<Tpetra::MultiVector<>> rigid_body_modes(const DofMaps& maps,
                                                     const BackgroundMesh& mesh);

/// Owned particle coordinates on maps.owned_nodes, one column per dimension (for multigrid's
/// distance-based aggregation).
Teuchos::RCP<Tpetra::MultiVector<>> particle_coordinates(const DofMaps& maps,
                                                         const BackgroundMesh& mesh);

/// Number of rigid-body modes in `dimension` space dimensions: 1, 3 or 6.
int rigid_body_mode_count(int dimension);

}  // namespace efg
