// A sparse LU factorization of a matrix distributed over the processes of a communicator, by
// MUMPS (Amestoy, Duff, L'Excellent, Koster, "A fully asynchronous multifrontal solver using
// distributed dynamic scheduling", SIAM J. Matrix Anal. Appl. 23(1), 2001; Debian's
// libmumps-dev). Multifrontal like UMFPACK (BLAS 3 on the dense fronts), but the fronts
// of the elimination tree are factored by all processes together, so a 2-rank run factors in
// about half the time where the one-process UMFPACK path gains nothing (docs/implicit.md).
//
// Each process hands over its own entries (global 0-based row and column positions; duplicates
// are summed); the right-hand side and the solution live on process 0 of the communicator.
// The symbolic analysis (fill-reducing ordering by PORD, on process 0) is kept while the pattern
// stays the same. Free of Trilinos.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace efg {

/// A factorization that met a null pivot (the message says where it came from).
class SingularMatrixError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class DistributedLU {
 public:
  explicit DistributedLU(MPI_Comm comm);
  DistributedLU(const DistributedLU&) = delete;
  DistributedLU& operator=(const DistributedLU&) = delete;
  ~DistributedLU();

  /// Factors the n x n matrix whose entries (rows[k], columns[k], values[k]) this process holds
  /// (collective). Throws SingularMatrixError when a pivot falls below 1e-14 of the scaled
  /// matrix's norm, std::runtime_error naming MUMPS' status when MUMPS fails otherwise (memory).
  void factor(std::int64_t n, std::vector<int> rows, std::vector<int> columns,
              std::vector<double> values);

  /// x = A^-1 b for `count` right-hand sides of length n stored one after another, on process 0;
  /// other processes pass nullptr (collective). Overwrites b_then_x with the solutions.
  void solve(double* b_then_x, int count);

  /// Nonzeros of L + U of the last factorization (all processes), for the log.
  std::int64_t factor_nonzeros() const { return factor_nonzeros_; }

 private:
  struct Instance;  // MUMPS' structure, kept out of this header
  std::unique_ptr<Instance> mumps_;
  std::vector<int> rows_, columns_;  // 1-based, as MUMPS keeps pointers to them
  std::vector<double> values_;
  std::int64_t n_ = 0, factor_nonzeros_ = 0;
  bool analysed_ = false;
};

}  // namespace efg
