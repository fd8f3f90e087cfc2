// The guard against folded material in explicit stages (issue 56, item 5): the background cells
// of the solid parts, carried by their particles (the cells' nodes) into the current
// configuration, must keep a positive Jacobian at every corner. A cell turned inside out means
// particles passed each other: the material folded through itself, which no continuum motion
// does. The integration points need not see it (a smoothed SCNI gradient averages over the cell's
// neighbours: a block crushed between plates folded, its particles beyond both plates, with every
// point's det F positive, and the run had reported success), so the cells are checked directly.
//
// Not checked: parts whose material erodes (failure_strain: eroded points leave the model and
// their particles may pass each other), shell parts, rigid bodies' blocks.
//
// A corner turned partly over is not a fold: a Taylor bar's particles at its held impact face
// (corner Jacobian -3.4 % of its reference value) and a mixed u-p rubber bar at a wall (-51 % with
// patch pressures) left their cells' corners so while the solution stayed right (energy balance
// < 1 %; the meshfree points do not use the current cell shape). The driver stops where a corner
// is mirrored (its Jacobian at minus its reference value or below) and warns once before that
// (drivers/ExplicitDriver).
#pragma once

#include <Tpetra_Vector.hpp>

#include <optional>
#include <string>
#include <vector>

#include "mesh/CellTopology.hpp"
#include "model/Model.hpp"

namespace efg {

class CellInversion {
 public:
  explicit CellInversion(const Model& model);

  /// An inverted cell: where (global cell and node numbers, 1-based for messages) and how.
  struct Inverted {
    long long cell = -1;      ///< the whole mesh's cell number, 1-based
    long long particle = -1;  ///< the whole mesh's node at the inverted corner, 1-based
    std::string part;
    double reference_det = 0, current_det = 0;  ///< that corner's Jacobian, reference and now
    double ratio() const { return current_det / reference_det; }
  };
  /// The most inverted cell over every rank (the smallest ratio of a corner's Jacobian now to
  /// its reference value, <= 0; the smallest cell number among equals; collective), or none.
  /// d_overlap: the displacements on the overlap dof map.
  std::optional<Inverted> most_inverted(const Tpetra::Vector<>& d_overlap) const;
  /// Cells checked on this rank.
  std::size_t size() const { return cells_.size(); }

 private:
  struct Cell {
    CellType type;
    long long number;             ///< whole mesh, 0-based
    std::vector<int> overlap;     ///< overlap node index of each node
    std::vector<long long> node;  ///< whole mesh node of each node
    std::size_t part;
    std::vector<double> corner_det;  ///< every corner's reference Jacobian
  };
  /// The node coordinates of a cell, displaced by d (overlap dofs; the reference without).
  std::vector<double> corners(const Cell& cell, const double* d) const;
  std::vector<Cell> cells_;
  std::vector<std::string> part_names_;
  std::vector<double> reference_;  ///< overlap node coordinates, dimension each
  int dim_;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
};

}  // namespace efg
