#include "operators/BulkSplit.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>

#include "operators/MixedPressure.hpp"

namespace efg {

std::string bulk_split_misfit(const ModelOperators& ops, const EssentialConditions& conditions) {
  const auto* mixed = ops.mixed();
  if (mixed == nullptr || !mixed->has_bulk_excess()) return "no mixed u-p part with nu above 1/4";
  bool weak = false;
  conditions.cell_pressure_tractions(Vector(ops.model().maps.overlap_dofs), weak);
  if (weak) return "a Nitsche or penalty condition on a mixed u-p part";
  return "";
}

BulkCoupling::BulkCoupling(const ModelOperators& ops, const EssentialConditions& conditions)
    : ops_(ops),
      conditions_(conditions),
      constrained_(conditions.constrained_rows()),
      x_overlap_(ops.model().maps.overlap_dofs),
      y_overlap_(ops.model().maps.overlap_dofs) {
  const auto& mixed = *ops.mixed();
  const auto& model = ops.model();
  bool weak = false;
  tractions_ = conditions.cell_pressure_tractions(x_overlap_, weak);  // the groups: any state
  cells_ = mixed.cell_count();
  std::vector<long long> owned(cells_);
  mixed.bulk_group_ids(owned.data());
  std::vector<long long> overlap = owned;
  for (const auto& t : tractions_) overlap.push_back(mixed.bulk_group_id(t.part, t.group));
  std::sort(overlap.begin() + static_cast<std::ptrdiff_t>(cells_), overlap.end());
  overlap.erase(std::unique(overlap.begin() + static_cast<std::ptrdiff_t>(cells_), overlap.end()),
                overlap.end());
  {
    // a traction's cell owned here is already among the first cells_ entries
    std::vector<long long> mine(owned);
    std::sort(mine.begin(), mine.end());
    overlap.erase(std::remove_if(
                      overlap.begin() + static_cast<std::ptrdiff_t>(cells_), overlap.end(),
                      [&](long long g) { return std::binary_search(mine.begin(), mine.end(), g); }),
                  overlap.end());
  }
  const auto comm = model.maps.owned_dofs->getComm();
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  using GO = Tpetra::Map<>::global_ordinal_type;
  const std::vector<GO> owned_go(owned.begin(), owned.end()),
      overlap_go(overlap.begin(), overlap.end());
  owned_cells_ =
      Teuchos::rcp(new Tpetra::Map<>(invalid, Teuchos::ArrayView<const GO>(owned_go), 0, comm));
  overlap_cells_ =
      Teuchos::rcp(new Tpetra::Map<>(invalid, Teuchos::ArrayView<const GO>(overlap_go), 0, comm));
  import_ = Teuchos::rcp(new Tpetra::Import<>(owned_cells_, overlap_cells_));
  q_owned_ = Teuchos::rcp(new Vector(owned_cells_));
  q_overlap_ = Teuchos::rcp(new Vector(overlap_cells_));
  {
    int mine = tractions_.empty() ? 0 : 1, any = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, mine, Teuchos::outArg(any));
    any_tractions_ = any != 0;
  }
  for (const auto& t : tractions_)
    traction_cell_.push_back(overlap_cells_->getLocalElement(mixed.bulk_group_id(t.part, t.group)));
  // The collocation rows follow the largest of E and 3 kappa (EssentialConditions); in A the
  // mixed parts' kappa is kappa_0.
  double reference = 0;
  for (const auto& m : model.scene.materials)
    reference = std::max(reference, m.constants.at("youngs_modulus"));
  for (std::size_t p = 0; p < model.parts.size(); ++p)
    reference =
        std::max(reference, 3 * (mixed.mixed(p) ? mixed.bulk_reference(p)
                                                : ops.solid().history().part(p).law.bulk_modulus));
  row_factor_ = conditions.row_modulus() > 0 ? reference / conditions.row_modulus() : 1.0;
}

void BulkCoupling::pressures(const Vector& x_owned, double* q) const {
  ops_.to_overlap(x_owned, x_overlap_);
  ops_.mixed()->bulk_excess_pressures(x_overlap_, q);
}

void BulkCoupling::forces(const double* q, Vector& y_owned) const {
  y_overlap_.putScalar(0.0);
  ops_.mixed()->add_cell_forces(q, y_overlap_);
  if (any_tractions_) {  // collective (the import)
    auto& q_owned = *q_owned_;
    auto& q_overlap = *q_overlap_;
    {
      auto v = q_owned.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t c = 0; c < cells_; ++c) v(c, 0) = q[c];
    }
    q_overlap.doImport(q_owned, *import_, Tpetra::INSERT);
    const auto qc = q_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto y = y_overlap_.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t k = 0; k < tractions_.size(); ++k) {
      const auto& t = tractions_[k];
      // the cell's excess pressure kappa_1 theta_c = q_c / V_c
      const double p = qc(static_cast<std::size_t>(traction_cell_[k]), 0) / t.volume;
      for (std::size_t r = 0; r < t.rows.size(); ++r)
        y(static_cast<std::size_t>(t.rows[r]), 0) += t.coefficient[r] * p;
    }
  }
  ops_.to_owned(y_overlap_, y_owned);
  for (int r : constrained_) y_owned.replaceLocalValue(r, 0.0);
}

Teuchos::RCP<const Tpetra::CrsMatrix<>> BulkCoupling::relieved(const Tpetra::CrsMatrix<>& K,
                                                               const FEMatrix& relieved_tangent,
                                                               const Vector& d_overlap) {
  ops_.mixed()->bulk_state(d_overlap);
  bool weak = false;
  tractions_ = conditions_.cell_pressure_tractions(d_overlap, weak);  // same points, same order
  auto A = Teuchos::rcp(new Tpetra::CrsMatrix<>(relieved_tangent, Teuchos::Copy));
  A->resumeFill();
  // The collocation rows: K's (same graph, so the same local columns), scaled to kappa_0's
  // modulus.
  Teuchos::Array<int> cols;
  Teuchos::Array<double> vals;
  for (int row : constrained_) {
    const auto n = K.getNumEntriesInLocalRow(row);
    cols.resize(n);
    vals.resize(n);
    std::size_t count = 0;
    K.getLocalRowCopy(row, cols(), vals(), count);
    for (auto& v : vals) v *= row_factor_;
    A->replaceLocalValues(row, cols(), vals());
  }
  A->fillComplete(K.getDomainMap(), K.getRangeMap());
  return A;
}

}  // namespace efg
