#include "operators/CouplingGraph.hpp"

#include <algorithm>

namespace efg {

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
  auto graph =
      Teuchos::rcp(new FEGraph(maps.owned_dofs, maps.overlap_dofs, maps.overlap_dofs, counts));
  graph->beginAssembly();
  std::vector<int> cols;
  for (std::size_t n = 0; n < rows_.size(); ++n) {
    cols.clear();
    for (int m : rows_[n])
      for (int c = 0; c < dim; ++c) cols.push_back(m * dim + c);
    for (int c = 0; c < dim; ++c)
      graph->insertLocalIndices(static_cast<int>(n) * dim + c, static_cast<int>(cols.size()),
                                cols.data());
  }
  graph->endAssembly();
  return graph;
}

}  // namespace efg
