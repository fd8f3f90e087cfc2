// The sparsity of the stiffness matrix from support overlap: particles I and J are coupled when
// both reach a common integration point (or a constrained node's row). Built once per model as a
// Tpetra::FECrsGraph (owned rows, plus the ghost rows this rank contributes to), with every
// component of I coupled to every component of J. Newton iterations only refill the values.
#pragma once

#include <Tpetra_FECrsGraph.hpp>

#include <set>
#include <vector>

#include "parallel/DofMaps.hpp"

namespace efg {

using FEGraph = Tpetra::FECrsGraph<>;

class CouplingGraph {
 public:
  explicit CouplingGraph(std::size_t overlap_nodes) : rows_(overlap_nodes) {}
  /// Couples every pair of the given overlap nodes.
  void add_clique(const int* nodes, std::size_t count);
  /// Couples overlap node `row` to each of `cols`.
  void add_row(int row, const int* cols, std::size_t count);
  /// Builds the graph on the dof maps; columns are the overlap dofs (local ids = overlap ids).
  Teuchos::RCP<const FEGraph> build(const DofMaps& maps) const;

 private:
  std::vector<std::set<int>> rows_;
};

}  // namespace efg
