#include "run/RunRecorder.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <cerrno>
#include <filesystem>
#include <iomanip>

#include "core/Log.hpp"
#include "io/WritePaths.hpp"
#include "parallel/Collective.hpp"
#include "run/OutputFields.hpp"

namespace efg {
namespace {
/// Strain magnitude |sym grad u| beyond which a small-strain part is warned about.
constexpr double kSmallStrainLimit = 0.2;
}  // namespace

RunRecorder::RunRecorder(const CommPtr& comm, const Model& model, const ModelOperators& ops,
                         StaticProblem* problem, const std::string& path)
    : comm_(comm),
      model_(model),
      ops_(ops),
      problem_(problem),
      path_(path),
      columns_(output_columns(model.scene.output.fields, model.mesh.dimension)),
      history_(model),
      output_(comm, path, model.mesh, model.maps.owned_nodes,
              OutputLayout{columns_, cell_columns(model.scene.output.fields), history_.names()},
              model.scene.title.empty() ? model.scene.name : model.scene.title, output_cells(model),
              model.scene.output.per_rank_files),
      nodal_volume_(nodal_volume_column(model)),
      d_overlap_(model.maps.overlap_dofs),
      v_overlap_(model.maps.overlap_dofs),
      a_overlap_(model.maps.overlap_dofs) {
  if (!model.scene.output.history.empty() && comm->getRank() == 0) {
    csv_final_ = (std::filesystem::path(path).parent_path() / model.scene.output.history).string();
    create_fresh_file(csv_final_ + ".part");  // never through a link planted at the name
    csv_ = std::make_unique<std::ofstream>(csv_final_ + ".part");  // renamed on success
    *csv_ << history_.csv_header() << "\n";
  }
}

// Small-strain parts: particles passing through each other stop the run before the record is
// written; strains beyond what the formulation represents are announced once.
void RunRecorder::check_kinematics(double time) {
  double mine = 0, largest = 0;
  run_collectively(comm_, [&] { mine = ops_.solid().check_small_strain(d_overlap_, time); });
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(largest));
  if (largest > kSmallStrainLimit && !strain_warned_) {
    strain_warned_ = true;
    Log::warning("strains of " + std::to_string(100 * largest) +
                 " % at t = " + std::to_string(time) + " in a small-strain part: beyond " +
                 std::to_string(static_cast<int>(100 * kSmallStrainLimit)) +
                 " % its results are no longer a good approximation; use formulation "
                 "total_lagrangian (model neo_hookean, or j2_plasticity at finite strain)");
  }
}

void RunRecorder::write(const RunState& s) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: output"));
  ops_.to_overlap(s.d, d_overlap_);
  check_kinematics(s.time);
  ops_.to_overlap(s.v, v_overlap_);
  ops_.to_overlap(s.a, a_overlap_);
  const auto reactions = s.reactions_from_driver ? s.reactions
                         : problem_              ? problem_->reactions(s.d)
                                                 : std::vector<std::array<double, 3>>();
  const auto globals = history_.values(ops_, s, d_overlap_, v_overlap_, reactions);
  const auto values = state_columns(model_, ops_.solid(), d_overlap_, &v_overlap_, &a_overlap_,
                                    ops_.mixed(), nodal_volume_);
  ResultsOutput::MultiVector nodal(model_.maps.owned_nodes, columns_.size());
  {
    auto view = nodal.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t c = 0; c < values.size(); ++c)
      for (std::size_t i = 0; i < values[c].size(); ++i) view(i, c) = values[c][i];
  }
  if (output_.cell_map()) {
    const auto cells = cell_values(model_, ops_.mixed(), d_overlap_);
    ResultsOutput::MultiVector cell(output_.cell_map(), cells.size());
    {
      auto view = cell.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t c = 0; c < cells.size(); ++c)
        for (std::size_t i = 0; i < cells[c].size(); ++i) view(i, c) = cells[c][i];
    }
    output_.write(s.time, nodal, globals, &cell);
  } else {
    output_.write(s.time, nodal, globals);
  }
  last_globals_ = globals;
  if (csv_) {
    *csv_ << std::setprecision(12) << s.time;
    for (double g : globals) *csv_ << "," << g;
    *csv_ << "\n" << std::flush;
    if (!*csv_)
      throw std::runtime_error("writing the history '" + csv_final_ + ".part' failed" +
                               os_reason(errno));
  }
  ++records_;
}

RunRecorder::~RunRecorder() {
  if (!csv_) return;
  csv_->close();
  std::error_code ec;
  std::filesystem::remove(csv_final_ + ".part", ec);
}

void RunRecorder::keep_partial() {
  output_.close_partial();
  if (csv_) csv_->close();
  csv_.reset();
  // (one file per rank: every rank's piece keeps its ".part")
  const bool pieces = writes_pieces(model_.scene.output.per_rank_files, comm_->getSize());
  Log::info("results up to the failure: " +
            (pieces ? piece_path(path_, comm_->getSize(), 0) + ".part ..." : path_ + ".part") +
            (csv_final_.empty() ? std::string() : " and " + csv_final_ + ".part"));
}

void RunRecorder::close() {
  output_.close();
  if (csv_) {
    csv_->close();
    csv_.reset();
    std::filesystem::rename(csv_final_ + ".part", csv_final_);
  }
}

}  // namespace efg
