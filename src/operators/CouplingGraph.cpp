#include "operators/CouplingGraph.hpp"

namespace efg {

void CouplingGraph::add_clique(const int* nodes, std::size_t count) {
  for (std::size_t a = 0; a < count; ++a)
    rows_[static_cast<std::size_t>(nodes[a])].insert(nodes, nodes + count);
}

void CouplingGraph::add_row(int row, const int* cols, std::size_t count) {
  rows_[static_cast<std::size_t>(row)].insert(cols, cols + count);
  rows_[static_cast<std::size_t>(row)].insert(row);  // keep the diagonal
}

Teuchos::RCP<const FEGraph> CouplingGraph::build(const DofMaps& maps) const {
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
