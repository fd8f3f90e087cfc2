#include "solvers/DistributedLU.hpp"

#include <dmumps_c.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace efg {
namespace {

// MUMPS' control and information arrays are documented 1-based (ICNTL(7), INFOG(1), ...).
MUMPS_INT& icntl(DMUMPS_STRUC_C& id, int i) {
  return id.icntl[i - 1];
}
MUMPS_INT infog(const DMUMPS_STRUC_C& id, int i) {
  return id.infog[i - 1];
}

std::string failure(const DMUMPS_STRUC_C& id, const char* phase) {
  const int code = infog(id, 1), detail = infog(id, 2);
  std::string why;
  switch (code) {
    case -10:
      why = "the matrix is numerically singular";
      break;
    case -8:
    case -9:
    case -13:
    case -14:
    case -15:
    case -17:
      why = "out of memory (INFOG(1) = " + std::to_string(code) + ")";
      break;
    default:
      why = "MUMPS INFOG(1) = " + std::to_string(code) + ", INFOG(2) = " + std::to_string(detail);
  }
  return std::string("MUMPS ") + phase + " failed: " + why;
}

}  // namespace

struct DistributedLU::Instance {
  DMUMPS_STRUC_C id{};
};

DistributedLU::DistributedLU(MPI_Comm comm) : mumps_(std::make_unique<Instance>()) {
  auto& id = mumps_->id;
  id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
  id.par = 1;  // process 0 factors too
  id.sym = 0;  // general: the collocation rows of essential conditions are not symmetric
  id.job = -1;
  dmumps_c(&id);
  if (infog(id, 1) < 0) throw std::runtime_error(failure(id, "initialization"));
  // Silent: errors are reported through INFOG and turned into exceptions here.
  icntl(id, 1) = -1;
  icntl(id, 2) = -1;
  icntl(id, 3) = -1;
  icntl(id, 4) = 0;
  icntl(id, 18) = 3;  // each process gives its own entries (distributed assembled matrix)
  // Sequential ordering: MUMPS' automatic choice. Debian's MUMPS 5.5 has neither sequential
  // Scotch nor METIS built in: asked for either (ICNTL(7) = 3 or 5) it chooses itself, PORD
  // (Schulze 2001) on the 8,514-dof beam (INFOG(7) = 4, 2.39 GFlop; AMD 2.26, AMF 3.52, QAMD
  // 2.26). PORD forced on small 3D matrices stops with "no valid number of stages in
  // multisector" (the 135-dof hex8 patch test): the automatic choice avoids it there.
  icntl(id, 7) = 7;
  // Sequential analysis: Debian's MUMPS 5.5 answers parallel analysis (ICNTL(28) = 2, PT-Scotch)
  // with INFOG(1) = -38 (measured); the ordering takes 2 s of a 17 s factorization at 132k dofs.
  icntl(id, 28) = 1;
  icntl(id, 14) = 50;  // 50 % more working space than the analysis estimates (delayed pivots)
  icntl(id, 24) = 1;   // detect null pivots instead of perturbing them
  id.cntl[2] = 1e-14;  // CNTL(3): a pivot below 1e-14 of the scaled matrix's norm is null
}

DistributedLU::~DistributedLU() {
  auto& id = mumps_->id;
  id.job = -2;
  dmumps_c(&id);
}

void DistributedLU::factor(std::int64_t n, std::vector<int> rows, std::vector<int> columns,
                           std::vector<double> values) {
  auto& id = mumps_->id;
  for (auto& r : rows) ++r;
  for (auto& c : columns) ++c;
  // The analysis is kept while every process's pattern is the same as before.
  int same = analysed_ && n == n_ && rows == rows_ && columns == columns_ ? 1 : 0, all_same = 0;
  MPI_Comm comm = MPI_Comm_f2c(id.comm_fortran);
  MPI_Allreduce(&same, &all_same, 1, MPI_INT, MPI_MIN, comm);
  n_ = n;
  rows_ = std::move(rows);
  columns_ = std::move(columns);
  values_ = std::move(values);
  id.n = static_cast<MUMPS_INT>(n);
  id.nnz_loc = static_cast<MUMPS_INT8>(values_.size());
  id.irn_loc = rows_.data();
  id.jcn_loc = columns_.data();
  id.a_loc = values_.data();
  if (!all_same) {
    id.job = 1;  // analysis: ordering and symbolic factorization
    dmumps_c(&id);
    if (infog(id, 1) < 0) {
      analysed_ = false;
      throw std::runtime_error(failure(id, "analysis"));
    }
  }
  // Numerical pivoting can delay pivots beyond the analysis' workspace estimate (INFOG(1) = -8
  // or -9): retry with twice the relaxation, as the MUMPS user guide advises.
  for (int attempt = 0;; ++attempt) {
    id.job = 2;
    dmumps_c(&id);
    const bool short_of_space = infog(id, 1) == -8 || infog(id, 1) == -9;
    if (!short_of_space || attempt == 3) break;
    icntl(id, 14) *= 2;
  }
  if (infog(id, 1) == -10) throw SingularMatrixError(failure(id, "factorization"));
  if (infog(id, 1) < 0) throw std::runtime_error(failure(id, "factorization"));
  analysed_ = true;
  if (infog(id, 28) > 0)
    throw SingularMatrixError("MUMPS factorization failed: the matrix is singular (" +
                              std::to_string(infog(id, 28)) + " null pivots)");
  // INFOG(29): entries in the factors; negative values count millions (MUMPS user guide).
  const auto entries = static_cast<std::int64_t>(infog(id, 29));
  factor_nonzeros_ = entries >= 0 ? entries : -entries * 1000000;
}

void DistributedLU::solve(double* b_then_x, int count) {
  auto& id = mumps_->id;
  id.rhs = b_then_x;
  id.nrhs = count;
  id.lrhs = static_cast<MUMPS_INT>(n_);
  id.job = 3;
  dmumps_c(&id);
  if (infog(id, 1) < 0) throw std::runtime_error(failure(id, "solve"));
}

}  // namespace efg
