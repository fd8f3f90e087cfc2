#include "shells/ShellMultipliers.hpp"

#include <TpetraExt_MatrixMatrix.hpp>

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>

#include "shells/ShellConstraints.hpp"

namespace efg {

ShellMultipliers::ShellMultipliers(const ShellConstraints& constraints, const Vector& mass_owned)
    : inv_mass_(mass_owned.getMap()),
      r_(mass_owned.getMap()),
      y_(mass_owned.getMap()),
      correction_(mass_owned.getMap()) {
  std::vector<double> values;
  C_ = constraints.collocation_matrix(values);
  row_supports_ = constraints.row_supports();
  impulse_.assign(row_supports_.size(), 0.0);
  const auto rows = C_->getRowMap();
  count_ = static_cast<long long>(rows->getGlobalNumElements());
  inv_mass_.reciprocal(mass_owned);
  if (count_ == 0) return;
  g_ = Teuchos::rcp(new Vector(rows));
  {
    auto g = g_->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < values.size(); ++k) g(k, 0) = values[k];
  }
  // A = (C M^-1/2) (C M^-1/2)^T, symmetric positive definite (C has full row rank: the
  // collocation rows the implicit stages factor).
  Vector inv_sqrt_mass(mass_owned.getMap());
  {
    auto s = inv_sqrt_mass.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto m = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < s.extent(0); ++k) s(k, 0) = 1.0 / std::sqrt(m(k, 0));
  }
  Tpetra::CrsMatrix<> scaled(*C_, Teuchos::Copy);
  scaled.rightScale(inv_sqrt_mass);
  auto A = Teuchos::rcp(new Tpetra::CrsMatrix<>(rows, 0));
  Tpetra::MatrixMatrix::Multiply(scaled, false, scaled, true, *A);
  solver_ = make_direct_preconditioner(Teuchos::ParameterList());
  solver_->set_map(rows);
  solver_->compute(A);
  r_ = Vector(rows);
  y_ = Vector(rows);
}

void ShellMultipliers::correct(Vector& d_owned, double dt, Vector* force_owned) const {
  if (count_ == 0) return;
  dt_ = dt;
  C_->apply(d_owned, r_);
  r_.update(-1.0, *g_, 1.0);
  solver_->apply(r_, y_, Teuchos::NO_TRANS, 1.0, 0.0);
  C_->apply(y_, correction_, Teuchos::TRANS);
  d_owned.elementWiseMultiply(-1.0, inv_mass_, correction_, 1.0);
  if (force_owned) force_owned->update(-1.0 / (dt * dt), correction_, 1.0);
}

void ShellMultipliers::set_values(const std::vector<double>& g) {
  if (count_ == 0) return;
  auto v = g_->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t k = 0; k < g.size(); ++k) v(k, 0) = g[k];
}

void ShellMultipliers::accumulate_impulse(double dt) {
  if (count_ == 0) return;
  const auto y = y_.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < impulse_.size(); ++k) impulse_[k] -= y(k, 0) / (dt_ * dt_) * dt;
}

std::vector<double> ShellMultipliers::mean_support_forces(std::size_t supports, double elapsed) {
  constexpr std::size_t nd = 5;
  std::vector<double> mine(supports * nd, 0.0), all(mine.size(), 0.0);
  if (count_ > 0) {
    const auto y = y_.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < row_supports_.size(); ++k) {
      const auto [support, component] = row_supports_[k];
      mine[static_cast<std::size_t>(support) * nd + static_cast<std::size_t>(component)] +=
          elapsed > 0 ? impulse_[k] / elapsed : -y(k, 0) / (dt_ * dt_);
    }
    std::fill(impulse_.begin(), impulse_.end(), 0.0);
  }
  if (!mine.empty())
    Teuchos::reduceAll(*inv_mass_.getMap()->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(mine.size()), mine.data(), all.data());
  return all;
}

}  // namespace efg
