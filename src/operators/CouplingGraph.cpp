#include "operators/CouplingGraph.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace efg {
namespace {

// An FECrsGraph whose rows arrive whole, sorted and unique, and are copied into their allocated
// storage. Tpetra 13.2's insertLocalIndices looks every new index up in the row so far (a linear
// scan up to 400 entries, a hash table above): quadratic in the row length, 0.23 s for the 3D
// block's 9,300 rows of some 360 columns where the tangent's values took 0.05 s. What the copy
// leaves Tpetra to do is what insertLocalIndicesImpl does after its search: count the row's
// entries and mark the structure modified; the rows being sorted and unique, fillComplete is told
// so (CrsGraph's protected state, as a subclass may).
class WholeRowGraph final : public FEGraph {
 public:
  using FEGraph::FEGraph;

  void set_rows(const std::vector<std::vector<int>>& node_rows, int dim) {
    auto indices = this->lclIndsUnpacked_wdv.getHostView(Tpetra::Access::ReadWrite);
    for (std::size_t n = 0; n < node_rows.size(); ++n)
      for (int c = 0; c < dim; ++c) {
        const auto row = static_cast<int>(n) * dim + c;
        const auto info = this->getRowInfo(row);
        const auto count = node_rows[n].size() * static_cast<std::size_t>(dim);
        if (info.numEntries != 0 || count > info.allocSize)
          throw std::logic_error("CouplingGraph: row " + std::to_string(row) +
                                 " has no room for its " + std::to_string(count) + " columns");
        auto* out = indices.data() + info.offset1D;
        for (int m : node_rows[n])
          for (int k = 0; k < dim; ++k) *out++ = m * dim + k;
        this->k_numRowEntries_(row) = count;
      }
    this->setLocallyModified();
    this->indicesAreSorted_ = true;
    this->noRedundancies_ = true;
  }
};

}  // namespace

void CouplingGraph::compact(std::size_t row) {
  auto& r = rows_[row];
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  sorted_[row] = r.size();
}

void CouplingGraph::append(std::size_t row, const int* cols, std::size_t count) {
  auto& r = rows_[row];
  r.insert(r.end(), cols, cols + count);
  if (r.size() > 2 * sorted_[row] + 64) compact(row);
}

void CouplingGraph::add_clique(const int* nodes, std::size_t count) {
  for (std::size_t a = 0; a < count; ++a) append(static_cast<std::size_t>(nodes[a]), nodes, count);
}

void CouplingGraph::add_row(int row, const int* cols, std::size_t count) {
  append(static_cast<std::size_t>(row), cols, count);
  append(static_cast<std::size_t>(row), &row, 1);  // keep the diagonal
}

Teuchos::RCP<const FEGraph> CouplingGraph::build(const DofMaps& maps) {
  for (std::size_t n = 0; n < rows_.size(); ++n) {
    compact(n);
    rows_[n].shrink_to_fit();
  }
  const int dim = maps.dofs_per_node;
  const auto dofs = maps.overlap_dofs->getNodeNumElements();
  Kokkos::DualView<std::size_t*, FEGraph::device_type> counts("efg::graph row counts", dofs);
  auto host = counts.view_host();
  for (std::size_t n = 0; n < rows_.size(); ++n)
    for (int c = 0; c < dim; ++c)
      host(n * static_cast<std::size_t>(dim) + static_cast<std::size_t>(c)) =
          rows_[n].size() * static_cast<std::size_t>(dim);
  counts.modify_host();
  counts.sync_device();
  auto graph = Teuchos::rcp(
      new WholeRowGraph(maps.owned_dofs, maps.overlap_dofs, maps.overlap_dofs, counts));
  graph->beginAssembly();
  graph->set_rows(rows_, dim);
  graph->endAssembly();
  return graph;
}

}  // namespace efg
