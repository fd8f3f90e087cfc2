#include "io/ResultsOutput.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <stdexcept>

#include "parallel/Collective.hpp"

namespace efg {

ResultsOutput::ResultsOutput(const CommPtr& comm, const std::string& path,
                             const BackgroundMesh& mesh, const Teuchos::RCP<const Map>& owned_nodes,
                             const OutputLayout& layout, const std::string& title,
                             const std::vector<GlobalOrdinal>& owned_cells)
    : comm_(comm), nodes_(mesh.node_count()) {
  std::vector<GlobalOrdinal> gids;
  if (comm->getRank() == 0)
    for (std::size_t n = 0; n < nodes_; ++n) gids.push_back(static_cast<GlobalOrdinal>(n));
  root_map_ = Teuchos::rcp(
      new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
              Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), static_cast<int>(gids.size())),
              0, comm));
  gather_ = Teuchos::rcp(new Tpetra::Import<>(owned_nodes, root_map_));
  if (!layout.element.empty()) {
    cells_ = mesh.cell_count();
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    cell_map_ = Teuchos::rcp(new Map(invalid,
                                     Teuchos::ArrayView<const GlobalOrdinal>(
                                         owned_cells.data(), static_cast<int>(owned_cells.size())),
                                     0, comm));
    std::vector<GlobalOrdinal> all;
    if (comm->getRank() == 0)
      for (std::size_t c = 0; c < cells_; ++c) all.push_back(static_cast<GlobalOrdinal>(c));
    cell_root_map_ = Teuchos::rcp(new Map(
        invalid, Teuchos::ArrayView<const GlobalOrdinal>(all.data(), static_cast<int>(all.size())),
        0, comm));
    cell_gather_ = Teuchos::rcp(new Tpetra::Import<>(cell_map_, cell_root_map_));
  }
  // Rank 0 creates the file; the others learn whether that worked so that all ranks agree.
  int ok = 1;
  std::string error;
  if (comm->getRank() == 0) {
    try {
      writer_ = std::make_unique<ExodusWriter>(path, mesh, layout, title);
    } catch (const std::exception& e) {
      ok = 0;
      error = e.what();
    }
  }
  Teuchos::broadcast(*comm, 0, &ok);
  if (!ok)
    throw std::runtime_error(comm->getRank() == 0 ? error
                                                  : "results file could not be created on rank 0");
}

void ResultsOutput::write(double time, const MultiVector& nodal, const std::vector<double>& global,
                          const MultiVector* cells) {
  MultiVector gathered(root_map_, nodal.getNumVectors());
  gathered.doImport(nodal, *gather_, Tpetra::INSERT);
  std::vector<std::vector<double>> element;
  if (cells) {
    MultiVector cell_values(cell_root_map_, cells->getNumVectors());  // zero where none given
    cell_values.doImport(*cells, *cell_gather_, Tpetra::INSERT);
    if (comm_->getRank() == 0) {
      const auto view = cell_values.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (std::size_t c = 0; c < cells->getNumVectors(); ++c) {
        element.emplace_back(cells_);
        for (std::size_t k = 0; k < cells_; ++k) element.back()[k] = view(k, c);
      }
    }
  }
  // Rank 0 writes; a refused record (a non-finite value) or a failed write is learned by all.
  run_collectively(comm_, [&] {
    if (comm_->getRank() != 0) return;
    std::vector<std::vector<double>> columns(nodal.getNumVectors(), std::vector<double>(nodes_));
    auto view = gathered.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t c = 0; c < columns.size(); ++c)
      for (std::size_t n = 0; n < nodes_; ++n) columns[c][n] = view(n, c);
    writer_->write_record(time, columns, element, global);
  });
}

void ResultsOutput::close() {
  run_collectively(comm_, [&] {
    if (writer_) writer_->close();
  });
}

void ResultsOutput::close_partial() {
  run_collectively(comm_, [&] {
    if (writer_) writer_->close(true);
  });
}

}  // namespace efg
