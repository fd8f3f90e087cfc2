// Parallel results output: each rank holds its owned particles' values. Gathered (the default): a
// Tpetra Import gathers them onto rank 0, which writes one Exodus file for the whole model (no
// join step needed). Per rank: every rank imports the values of its piece of the mesh
// (mesh/MeshPiece.hpp, its own nodes and the nodes of its cells) and writes its own file,
// "<path>.<ranks>.<rank>" as SEACAS names decomposed files; `epu -auto <path>.<ranks>.<0...>`
// joins them. Debian's Exodus 6.02 has no parallel (ex_create_par) writing, hence one file each.
#pragma once

#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include <memory>
#include <string>
#include <vector>

#include "io/ExodusWriter.hpp"
#include "parallel/DofMaps.hpp"

namespace efg {

class ResultsOutput {
 public:
  using MultiVector = Tpetra::MultiVector<double>;

  /// Collective. `layout.nodal` names the columns of the owned-node multivectors passed to write();
  /// `layout.element` those of the cell multivectors, on the map of `owned_cells` (global cell
  /// indices this rank provides; cells no rank provides are written as 0). `per_rank`: one file
  /// per rank (piece_path) instead of the gathered one.
  ResultsOutput(const CommPtr& comm, const std::string& path, const BackgroundMesh& mesh,
                const Teuchos::RCP<const Map>& owned_nodes, const OutputLayout& layout,
                const std::string& title, const std::vector<GlobalOrdinal>& owned_cells = {},
                bool per_rank = false);

  /// Collective: gathers `nodal` (owned map, one column per layout.nodal name) and `cells` (on
  /// cell_map(), one column per layout.element name; null without element fields) and writes a
  /// record.
  void write(double time, const MultiVector& nodal, const std::vector<double>& global,
             const MultiVector* cells = nullptr);
  const Teuchos::RCP<const Map>& cell_map() const { return cell_map_; }
  /// Collective: closes and renames the file (on rank 0, or each rank's piece).
  void close();
  /// Collective: closes the file of a failed run, which stays "<path>.part" (an earlier result at
  /// <path> is not replaced by a failed run).
  void close_partial();

 private:
  CommPtr comm_;
  Teuchos::RCP<const Map> root_map_;
  Teuchos::RCP<Tpetra::Import<>> gather_;
  Teuchos::RCP<const Map> cell_map_, cell_root_map_;
  Teuchos::RCP<Tpetra::Import<>> cell_gather_;
  std::size_t cells_ = 0;
  std::unique_ptr<ExodusWriter> writer_;  // rank 0 only when gathered
  std::size_t nodes_ = 0;
};

/// Whether results asked for one file per rank are written in pieces: on one rank the piece is
/// the whole mesh, and the one file is written.
inline bool writes_pieces(bool per_rank, int ranks) {
  return per_rank && ranks > 1;
}

/// The file of rank `rank`'s piece among `ranks`: "<path>.<ranks>.<rank>", the rank zero-padded
/// to the digits of `ranks` (the naming epu and the other SEACAS tools expect).
std::string piece_path(const std::string& path, int ranks, int rank);

}  // namespace efg
