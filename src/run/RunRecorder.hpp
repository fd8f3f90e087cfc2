// The records of one run: every output record (Exodus nodal fields and global quantities, and the
// history CSV), the small-strain validity check before each record, and what a failure keeps.
// Both files are written as NAME.part and renamed only when the run succeeds; a failed run leaves
// its records in the .part files and never replaces an earlier result of the same name.
#pragma once

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "drivers/RunState.hpp"
#include "drivers/StaticProblem.hpp"
#include "io/ResultsOutput.hpp"
#include "operators/ModelOperators.hpp"
#include "run/RunHistory.hpp"

namespace efg {

class RunRecorder {
 public:
  /// `problem` (may be null) gives the reactions of records the drivers do not fill.
  RunRecorder(const CommPtr& comm, const Model& model, const ModelOperators& ops,
              StaticProblem* problem, const std::string& path);

  /// Writes one record of `state` (collective). Throws NumericalError when a small-strain part
  /// has particles passing through each other or a value is not finite.
  void write(const RunState& state);
  /// After a failure: closes both files as .part and names them in the log (collective).
  void keep_partial();
  /// After success: closes and renames both files (collective).
  void close();
  /// Neither closed nor kept (bad input or an unexpected error after the output opened): the
  /// history's .part is removed, as the results writer removes its own (exit 2 writes nothing).
  ~RunRecorder();
  RunRecorder(const RunRecorder&) = delete;
  RunRecorder& operator=(const RunRecorder&) = delete;

  int records() const { return records_; }
  const std::vector<double>& last_globals() const { return last_globals_; }
  const std::vector<std::string>& global_names() const { return history_.names(); }

 private:
  void check_kinematics(double time);

  CommPtr comm_;
  const Model& model_;
  const ModelOperators& ops_;
  StaticProblem* problem_;
  std::string path_, csv_final_;
  std::vector<std::string> columns_;
  RunHistory history_;
  ResultsOutput output_;
  std::vector<double> nodal_volume_;  ///< lumped nodal volumes, once per run (when written)
  std::unique_ptr<std::ofstream> csv_;
  Vector d_overlap_, v_overlap_, a_overlap_;
  std::vector<double> last_globals_;
  int records_ = 0;
  bool strain_warned_ = false;
};

}  // namespace efg
