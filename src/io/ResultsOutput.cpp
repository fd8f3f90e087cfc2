#include "io/ResultsOutput.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_OrdinalTraits.hpp>

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "mesh/MeshPiece.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"

namespace efg {
namespace {

Teuchos::RCP<const Map> map_of(const std::vector<GlobalOrdinal>& gids, const CommPtr& comm) {
  return Teuchos::rcp(
      new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
              Teuchos::ArrayView<const GlobalOrdinal>(gids.data(), static_cast<int>(gids.size())),
              0, comm));
}

std::vector<GlobalOrdinal> first_indices(std::size_t count) {
  std::vector<GlobalOrdinal> gids(count);
  for (std::size_t i = 0; i < count; ++i) gids[i] = static_cast<GlobalOrdinal>(i);
  return gids;
}

// The whole mesh's index of each of `indices` (nodes or cells of `mesh`, a whole mesh or a
// rank's part of one).
std::vector<GlobalIndex> whole_indices(const std::vector<LocalIndex>& indices,
                                       const BackgroundMesh& mesh, bool cells) {
  std::vector<GlobalIndex> ids;
  ids.reserve(indices.size());
  for (auto i : indices) {
    const auto k = static_cast<std::size_t>(i);
    ids.push_back(cells ? mesh.global_cell(k) : mesh.global_node(k));
  }
  return ids;
}

std::vector<GlobalOrdinal> global_ordinals(const std::vector<GlobalIndex>& indices) {
  return std::vector<GlobalOrdinal>(indices.begin(), indices.end());
}

}  // namespace

std::string piece_path(const std::string& path, int ranks, int rank) {
  std::ostringstream name;
  name << path << '.' << ranks << '.' << std::setw(static_cast<int>(std::to_string(ranks).size()))
       << std::setfill('0') << rank;
  return name.str();
}

ResultsOutput::ResultsOutput(const CommPtr& comm, const std::string& path,
                             const BackgroundMesh& mesh, const Teuchos::RCP<const Map>& owned_nodes,
                             const OutputLayout& layout, const std::string& title,
                             const std::vector<GlobalOrdinal>& owned_cells, bool per_rank)
    : comm_(comm) {
  const bool root = comm->getRank() == 0;
  per_rank = writes_pieces(per_rank, comm->getSize());
  // What this rank writes: the whole mesh (rank 0, gathered), its piece, or nothing.
  // A rank's part of a mesh read in slices is never gathered (no rank holds the whole mesh).
  if (mesh.is_part() && !per_rank && comm->getSize() > 1)
    throw std::logic_error("ResultsOutput: a mesh read in slices is written one file per rank");
  MeshPiece piece;
  ExodusPieceIds ids;
  if (per_rank) {
    piece = mesh_piece(mesh, [&](LocalIndex n) {
      return owned_nodes->isNodeGlobalElement(
          static_cast<GlobalOrdinal>(mesh.global_node(static_cast<std::size_t>(n))));
    });
    ids = {whole_indices(piece.nodes, mesh, false), whole_indices(piece.cells, mesh, true),
           comm->getSize()};
  }
  const BackgroundMesh& written = per_rank ? piece.mesh : mesh;
  const bool writes = per_rank || root;
  nodes_ = writes ? written.node_count() : 0;
  root_map_ = map_of(per_rank ? global_ordinals(ids.nodes) : first_indices(nodes_), comm);
  gather_ = Teuchos::rcp(new Tpetra::Import<>(owned_nodes, root_map_));
  if (!layout.element.empty()) {
    cells_ = writes ? written.cell_count() : 0;
    cell_map_ = map_of(owned_cells, comm);
    cell_root_map_ = map_of(per_rank ? global_ordinals(ids.cells) : first_indices(cells_), comm);
    cell_gather_ = Teuchos::rcp(new Tpetra::Import<>(cell_map_, cell_root_map_));
  }
  // The ranks that write create their files; all ranks learn whether that worked.
  run_collectively(comm, [&] {
    if (!writes) return;
    if (!per_rank) {
      writer_ = std::make_unique<ExodusWriter>(path, mesh, layout, title);
      return;
    }
    writer_ = std::make_unique<ExodusWriter>(piece_path(path, comm->getSize(), comm->getRank()),
                                             piece.mesh, layout, title, &ids);
  });
}

void ResultsOutput::write(double time, const MultiVector& nodal, const std::vector<double>& global,
                          const MultiVector* cells) {
  MultiVector gathered(root_map_, nodal.getNumVectors());
  gathered.doImport(nodal, *gather_, Tpetra::INSERT);
  std::vector<std::vector<double>> element;
  if (cells) {
    MultiVector cell_values(cell_root_map_, cells->getNumVectors());  // zero where none given
    cell_values.doImport(*cells, *cell_gather_, Tpetra::INSERT);
    if (writer_) {
      const auto view = cell_values.getLocalViewHost(Tpetra::Access::ReadOnly);
      for (std::size_t c = 0; c < cells->getNumVectors(); ++c) {
        element.emplace_back(cells_);
        for (std::size_t k = 0; k < cells_; ++k) element.back()[k] = view(k, c);
      }
    }
  }
  // The writing ranks write; a refused record (a non-finite value) or a failed write is learned
  // by all.
  run_collectively(comm_, [&] {
    fault_point("output");
    if (!writer_) return;
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
