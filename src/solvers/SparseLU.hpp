// A sparse LU factorization of one process's square matrix by UMFPACK (Davis, "Algorithm 832:
// UMFPACK V4.3 - an unsymmetric-pattern multifrontal method", ACM TOMS 30(2), 2004; Debian's
// libsuitesparse-dev). Multifrontal: the dense frontal matrices go through BLAS 3, which is why it
// factors the meshfree Jacobians (80-160 couplings per row) many times faster than KLU2's
// left-looking sparse kernels (docs/implicit.md, measured table).
//
// The matrix is handed over row by row (compressed sparse rows, 0-based, any column order within
// a row); UMFPACK stores columns, so it factors the transpose and every solve asks for the
// transposed system (UMFPACK_Aat), which is the original one. Free of Trilinos.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace efg {

class SparseLU {
 public:
  SparseLU() = default;
  SparseLU(const SparseLU&) = delete;
  SparseLU& operator=(const SparseLU&) = delete;
  ~SparseLU();

  /// Factors the n x n matrix with rows [row_start[i], row_start[i+1]) of (columns, values).
  /// The symbolic analysis (ordering) is kept while the sparsity pattern stays the same.
  /// Throws std::runtime_error naming UMFPACK's status when the matrix is singular or invalid.
  void factor(std::int64_t n, std::vector<std::int64_t> row_start,
              std::vector<std::int64_t> columns, std::vector<double> values);

  /// x = A^-1 b (b and x of length n, distinct).
  void solve(const double* b, double* x) const;

  /// Nonzeros of L + U of the last factorization (for the log).
  std::int64_t factor_nonzeros() const { return factor_nonzeros_; }

 private:
  void free_numeric();
  void free_symbolic();

  std::int64_t n_ = 0;
  // The pattern in UMFPACK's form (column pointers / row indices of the transpose = our rows),
  // each row's columns ascending; values in the same order.
  std::vector<std::int64_t> start_, index_;
  std::vector<double> value_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::int64_t factor_nonzeros_ = 0;
};

}  // namespace efg
