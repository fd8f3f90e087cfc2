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

  /// Collective. `layout.nodal` names the columns of the owned-node multivectors passed to write().
  ResultsOutput(const CommPtr& comm, const std::string& path, const BackgroundMesh& mesh,
                const Teuchos::RCP<const Map>& owned_nodes, const OutputLayout& layout,
                const std::string& title);

  /// Collective: gathers `nodal` (owned map, one column per layout.nodal name) and writes a record.
  void write(double time, const MultiVector& nodal, const std::vector<double>& global);
  /// Collective: closes and renames the file on rank 0.
  void close();
  /// Collective: closes the file of a failed run, which stays "<path>.part" (an earlier result at
  /// <path> is not replaced by a failed run).
  void close_partial();

 private:
  CommPtr comm_;
  Teuchos::RCP<const Map> root_map_;
  Teuchos::RCP<Tpetra::Import<>> gather_;
  std::unique_ptr<ExodusWriter> writer_;  // rank 0 only
  std::size_t nodes_;
};

}  // namespace efg
