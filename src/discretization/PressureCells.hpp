// The pressure cells of a mixed u-p part: the groups of background cells that carry one constant
// pressure each (operators/MixedPressure).
//
// `cell` (default): one pressure per background cell. With the meshfree displacement this is the
// pairing of Q1/P0 finite elements, and it shares their spurious checkerboard mode (the inf-sup
// test finds an eigenvalue of 1e-5..1e-3 whose eigenvector alternates cell by cell): an implicit
// solve does not excite it, a sudden impact does (docs/mixed.md).
//
// `patch`: one pressure per vertex patch, the cells around an interior node of the part, chosen
// greedily in node order (2 x 2 cells on a structured quad mesh, 2 x 2 x 2 on a hex
// mesh). It is the macro-element remedy of Q1/P0 (Stenberg 1990, "Error analysis of some finite
// element methods for the Stokes problem", Math. Comp. 54; Brezzi & Fortin 1991, ch. VI): on a
// patch the alternating mode has no dilatation to hide in, and the inf-sup constant stays bounded
// on the whole mean-free pressure space (tests/verification/InfSupTest.cpp). Cells no patch took
// (along the boundary when a count is odd, or where the part is one cell thick) join the
// face-neighbouring patch with the fewest cells, so a patch holds 2^dim cells or a few more.
// The price is a constraint count 2^dim times lower: what the deviatoric stiffness does not
// control (perfectly plastic flow) may deform within a patch at constant patch volume, and the
// cell constraints' side effect of steadying SCNI on irregular particles is lost (docs/mixed.md
// measures both; integration scni_subcells restores the latter); hence `cell` stays the default.
//
// Every rank groups the replicated mesh alike; a group belongs to the owner of its lowest node.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

struct PressureCells {
  static constexpr std::uint32_t none = UINT32_MAX;
  std::vector<std::size_t> offsets{0};  ///< group g: cells[offsets[g] .. offsets[g + 1])
  std::vector<std::size_t> cells;       ///< global cell indices, ascending within a group
  std::vector<std::uint32_t> group;     ///< per global cell of the mesh: its group, or none

  std::size_t size() const { return offsets.size() - 1; }
};

/// The pressure cells of `part` by its `pressure_cells` choice (cell or patch).
PressureCells pressure_cells(const BackgroundMesh& mesh, const PartSpec& part);

/// Groups chosen over the whole mesh (`whole`, in whole-mesh cell indices; model/
/// SlicedPressurePatches) on a rank's part of it (mesh.global set): the groups of which the part
/// holds every cell, in its own cell indices, in the same order.
PressureCells groups_on_part(const BackgroundMesh& mesh, const PressureCells& whole);

/// One group per cell of `part` (the `cell` choice; also for a single cell's row).
PressureCells single_cells(const BackgroundMesh& mesh, const PartSpec& part);

/// The groups this rank owns (owner of the lowest node of the group's cells), ascending.
std::vector<std::size_t> owned_groups(const BackgroundMesh& mesh, const PressureCells& groups,
                                      const std::vector<int>& owner, int rank);

/// The largest distance between two nodes of one group (the ghost layer's reach beyond the
/// supports: a group's row couples the particles of its whole boundary).
double largest_group_diameter(const BackgroundMesh& mesh, const PressureCells& groups);

}  // namespace efg
