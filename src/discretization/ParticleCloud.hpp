// The particles of one meshfree part as one rank sees them: its owned particles first, then the
// ghosts it needs from other ranks. Reference positions, nodal volumes and support sizes live
// in the reference configuration (Lagrangian kernel): they never move with the material.
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

struct ParticleCloud {
  int dimension = 3;
  SectionSpec section;                ///< basis, kernel, support shape of the part
  std::vector<LocalIndex> mesh_node;  ///< mesh node (= global particle id) of each particle
  std::vector<double> position;       ///< reference position X, `dimension` per particle
  std::vector<double> support;  ///< support half-width a per direction, `dimension` per particle
  std::vector<double> volume;   ///< nodal volume from the background cells
  std::size_t owned_count = 0;  ///< particles [0, owned_count) are owned by this rank

  std::size_t size() const { return mesh_node.size(); }
  const double* x(std::size_t i) const {
    return position.data() + i * static_cast<std::size_t>(dimension);
  }
  const double* a(std::size_t i) const {
    return support.data() + i * static_cast<std::size_t>(dimension);
  }
};

/// Support half-widths of every node of `blocks` (a_d = dilation_d x h_d), indexed by mesh node;
/// nodes outside the blocks get 0. The nodal spacing h_d of node I is
///   spacing: edges     - the largest, over the background cells around I, of |e_d| of the cell
///                        edge e most nearly parallel to axis d (the distance between rows of
///                        nodes, also where cells are sheared against the axes);
///   spacing: cells     - the largest extent in direction d of the background cells around I
///                        (LS-DYNA IDILA = 0; on axis-aligned cells the same as edges);
///   spacing: neighbors - the largest |X_J,d - X_I,d| over the nodes J sharing a cell with I
///                        (IDILA = 1).
/// A sphere support takes a = dilation x max_d h_d in every direction. With per_part_support
/// every node gets the part's largest value per direction.
std::vector<double> support_sizes(const BackgroundMesh& mesh,
                                  const std::vector<std::string>& blocks,
                                  const SectionSpec& section);

/// The largest ratio, over the blocks' nodes and directions, of the spacing measured by the
/// cells' extents to the one measured along the cell edges (1 on axis-aligned cells): how much
/// wider `spacing: cells` makes the supports than the rows of particles where the cells are
/// sheared or curved against the axes (3.75 on Cook's panel at 16 x 16 cells).
double extent_over_rows(const BackgroundMesh& mesh, const std::vector<std::string>& blocks);

/// Mesh nodes of the blocks, ascending.
std::vector<LocalIndex> nodes_of_blocks(const BackgroundMesh& mesh,
                                        const std::vector<std::string>& blocks);

/// The cloud of `part`: its nodes owned here (owner[node] == rank) then the others listed in
/// `ghost_nodes` (mesh nodes, ascending; those outside the part are skipped).
ParticleCloud make_particle_cloud(const BackgroundMesh& mesh, const PartSpec& part,
                                  const std::vector<int>& owner, int rank,
                                  const std::vector<LocalIndex>& ghost_nodes);

/// Largest extent of a support along one coordinate axis from its particle: the largest
/// half-width a_d of a box support, the radius of a sphere. Every support lies inside the box
/// x_i +- this reach, so a search box of that half-width around a point finds every particle
/// whose support covers it.
double largest_support_reach(const ParticleCloud& cloud);

}  // namespace efg
