// Writes results as Exodus II: the background mesh once, then one record per output time with
// nodal (particle) fields, element fields and global variables. ParaView opens the files.
//
// Crash safety: everything is written to "<path>.part" and flushed after each record
// (ex_update), so a killed run leaves a readable partial file; close() renames it to <path>.
// The final name is therefore never a half-written file, and an earlier result at that name
// survives until the new run completes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/ExodusFile.hpp"
#include "mesh/BackgroundMesh.hpp"

namespace efg {

struct OutputLayout {
  std::vector<std::string> nodal;    ///< one value per mesh node
  std::vector<std::string> element;  ///< one value per cell, cells in block order
  std::vector<std::string> global;   ///< one value per record
};

/// A file holding one rank's piece of the results (mesh/MeshPiece.hpp): the whole mesh's index of
/// each of its nodes and cells (written as the Exodus node and element id maps, 1-based) and the
/// rank count, so that SEACAS `epu` joins the pieces into the whole mesh's numbering.
struct ExodusPieceIds {
  std::vector<GlobalIndex> nodes, cells;
  int ranks = 1;
};

/// Names "<base>_x", "<base>_y"[, "<base>_z"]: ParaView joins these into one vector field.
std::vector<std::string> vector_component_names(const std::string& base, int dimension);

class ExodusWriter {
 public:
  /// `piece`: the file is one rank's piece (its id maps are written); null for a whole mesh.
  ExodusWriter(const std::string& path, const BackgroundMesh& mesh, const OutputLayout& layout,
               const std::string& title, const ExodusPieceIds* piece = nullptr);
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;
  /// A writer neither closed nor kept (a run stopped by bad input or an unexpected error)
  /// removes its "<path>.part": such a failure writes nothing. A killed process leaves it.
  ~ExodusWriter();

  /// Appends one record. Each vector holds the fields in layout order.
  void write_record(double time, const std::vector<std::vector<double>>& nodal,
                    const std::vector<std::vector<double>>& element,
                    const std::vector<double>& global);
  /// Closes the file and renames it to its final path; with `keep_partial` (a failed run) the
  /// file stays "<path>.part" and an earlier result at <path> is left untouched.
  void close(bool keep_partial = false);

  const std::string& path() const { return path_; }
  int records() const { return records_; }

 private:
  void write_mesh(const BackgroundMesh& mesh, const std::string& title);
  void write_piece_ids(const ExodusPieceIds& piece);
  void write_variable_names(int type, const std::vector<std::string>& names);

  std::string path_;
  std::optional<exodus::File> file_;
  OutputLayout layout_;
  std::vector<std::pair<std::int64_t, std::size_t>> blocks_;  // id, cell count
  std::size_t nodes_ = 0;
  int records_ = 0;
  int checksum_variable_ = -1;  ///< the netCDF id of the record checksums (io/RecordChecksum)
  ExodusPieceIds piece_;        // empty maps for a whole mesh
};

}  // namespace efg
