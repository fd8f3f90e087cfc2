// Parallel results output: each rank holds its owned particles' values; a Tpetra Import gathers
// them onto rank 0, which writes one Exodus file for the whole model (no join step needed).
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
  /// indices this rank provides; cells no rank provides are written as 0).
  ResultsOutput(const CommPtr& comm, const std::string& path, const BackgroundMesh& mesh,
                const Teuchos::RCP<const Map>& owned_nodes, const OutputLayout& layout,
                const std::string& title, const std::vector<GlobalOrdinal>& owned_cells = {});

  /// Collective: gathers `nodal` (owned map, one column per layout.nodal name) and `cells` (on
  /// cell_map(), one column per layout.element name; null without element fields) and writes a
  /// record.
  void write(double time, const MultiVector& nodal, const std::vector<double>& global,
             const MultiVector* cells = nullptr);
  const Teuchos::RCP<const Map>& cell_map() const { return cell_map_; }
  /// Collective: closes and renames the file on rank 0.
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
  std::unique_ptr<ExodusWriter> writer_;  // rank 0 only
  std::size_t nodes_;
};

}  // namespace efg
