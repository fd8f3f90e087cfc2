#include "solvers/SparseLU.hpp"

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace efg {
namespace {

std::string status_text(long status) {
  switch (status) {
    case UMFPACK_WARNING_singular_matrix:
      return "the matrix is singular";
    case UMFPACK_ERROR_out_of_memory:
      return "out of memory";
    case UMFPACK_ERROR_invalid_matrix:
      return "invalid matrix structure";
    default:
      return "UMFPACK status " + std::to_string(status);
  }
}

std::string short_number(double x) {
  std::ostringstream out;
  out << std::setprecision(3) << x;
  return out.str();
}

void default_control(double (&control)[UMFPACK_CONTROL]) {
  umfpack_dl_defaults(control);
  // The Jacobians are structurally symmetric with a nearly symmetric, positive diagonal: the
  // symmetric strategy orders A + A^T and prefers diagonal pivots (UMFPACK user guide, 5.4).
  // The default ordering lets CHOLMOD try AMD and METIS and keep the one with less fill.
  control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
}

}  // namespace

SparseLU::~SparseLU() {
  free_numeric();
  free_symbolic();
}

void SparseLU::free_numeric() {
  if (numeric_) umfpack_dl_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void SparseLU::free_symbolic() {
  if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void SparseLU::factor(std::int64_t n, std::vector<std::int64_t> row_start,
                      std::vector<std::int64_t> columns, std::vector<double> values) {
  // UMFPACK wants each column's (here: row's) indices ascending without duplicates.
  std::vector<std::pair<std::int64_t, double>> row;
  for (std::int64_t i = 0; i < n; ++i) {
    const auto b = row_start[i], e = row_start[i + 1];
    row.clear();
    for (auto k = b; k < e; ++k) row.emplace_back(columns[k], values[k]);
    std::sort(row.begin(), row.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto k = b; k < e; ++k) columns[k] = row[k - b].first, values[k] = row[k - b].second;
  }
  const bool same_pattern = symbolic_ && n == n_ && row_start == start_ && columns == index_;
  n_ = n;
  start_ = std::move(row_start);
  index_ = std::move(columns);
  value_ = std::move(values);
  free_numeric();
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  default_control(control);
  using L = SuiteSparse_long;
  auto* Ap = reinterpret_cast<const L*>(start_.data());
  auto* Ai = reinterpret_cast<const L*>(index_.data());
  if (!same_pattern) {
    free_symbolic();
    const L status = umfpack_dl_symbolic(n, n, Ap, Ai, value_.data(), &symbolic_, control, info);
    if (status != UMFPACK_OK)
      throw std::runtime_error("UMFPACK symbolic analysis failed: " + status_text(status));
  }
  const L status = umfpack_dl_numeric(Ap, Ai, value_.data(), symbolic_, &numeric_, control, info);
  // UMFPACK flags only exactly zero pivots; a pivot at round-off level of the (row-scaled)
  // matrix is a singular matrix too (its reciprocal condition estimate min|u_ii| / max|u_ii|).
  const double rcond = info[UMFPACK_RCOND];
  if (status != UMFPACK_OK || !(rcond > 1e-14)) {
    free_numeric();
    throw std::runtime_error("UMFPACK factorization failed: " +
                             (status != UMFPACK_OK ? status_text(status)
                                                   : "the matrix is singular (pivot ratio " +
                                                         short_number(rcond) + ")"));
  }
  factor_nonzeros_ = static_cast<std::int64_t>(info[UMFPACK_LNZ] + info[UMFPACK_UNZ]);
}

void SparseLU::solve(const double* b, double* x) const {
  if (!numeric_) throw std::logic_error("SparseLU::solve before factor");
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  default_control(control);
  using L = SuiteSparse_long;
  // The stored matrix is our transpose: solve A^T x = b of it, i.e. our A x = b.
  const L status = umfpack_dl_solve(UMFPACK_Aat, reinterpret_cast<const L*>(start_.data()),
                                    reinterpret_cast<const L*>(index_.data()), value_.data(), x, b,
                                    numeric_, control, info);
  if (status != UMFPACK_OK)
    throw std::runtime_error("UMFPACK solve failed: " + status_text(status));
}

}  // namespace efg
