// The sparsity of the stiffness matrix from support overlap: particles I and J are coupled when
// both reach a common integration point (or a constrained node's row). Built once per model as a
// Tpetra::FECrsGraph (owned rows, plus the ghost rows this rank contributes to), with every
// component of I coupled to every component of J. Newton iterations only refill the values.
#pragma once

#include <Tpetra_FECrsGraph.hpp>

#include <vector>

#include "parallel/DofMaps.hpp"

namespace efg {

using FEGraph = Tpetra::FECrsGraph<>;

class CouplingGraph {
 public:
  explicit CouplingGraph(std::size_t overlap_nodes)
      : rows_(overlap_nodes), sorted_(overlap_nodes, 0) {}
  /// Couples every pair of the given overlap nodes.
  void add_clique(const int* nodes, std::size_t count);
  /// Couples overlap node `row` to each of `cols`.
  void add_row(int row, const int* cols, std::size_t count);
  /// Builds the graph on the dof maps; columns are the overlap dofs (local ids = overlap ids).
  /// Each row is sorted and unique from here on.
  Teuchos::RCP<const FEGraph> build(const DofMaps& maps);

 private:
  // A row collects its couplings unsorted and is sorted and made unique whenever it has doubled
  // since the last time (a clique adds its whole node list to each of its rows, so a row hears
  // of each neighbour many times): memory stays within twice the final row plus one clique, at 4
  // bytes an entry, where a std::set per row took about 40 (issue 20).
  void append(std::size_t row, const int* cols, std::size_t count);
  void compact(std::size_t row);
  std::vector<std::vector<int>> rows_;
  std::vector<std::size_t> sorted_;  ///< size of each row after its last compaction
};

}  // namespace efg
