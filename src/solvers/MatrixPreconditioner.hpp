// A preconditioner rebuilt from each new Jacobian, seen by Belos as a plain Tpetra operator
// (applied on the right, so GMRES measures the true residual). The model evaluator hands it to
// NOX as W_prec; `compute` runs once per Newton iteration, after the Jacobian is assembled.
// Four kinds (solvers/LinearSolverPlan.hpp): a direct LU factorization (MUMPS, UMFPACK, Amesos2),
// smoothed aggregation multigrid with rigid-body modes (MueLu) on the Jacobian or on an
// auxiliary finite element matrix, an Ifpack2 preconditioner.
#pragma once

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Operator.hpp>
#include <Tpetra_Vector.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solvers/LinearSolverPlan.hpp"

namespace efg {

class MatrixPreconditioner : public Tpetra::Operator<> {
 public:
  using Matrix = Tpetra::CrsMatrix<>;
  using MultiVector = Tpetra::MultiVector<>;
  using Map = Tpetra::Map<>;

  /// Builds (first call) or refreshes (later calls: same sparsity, new values) from K. Throws
  /// NumericalError when K cannot be factored (singular).
  virtual void compute(const Teuchos::RCP<const Matrix>& K) = 0;

  /// Seconds spent in compute() so far (setup share of the linear solves).
  double setup_seconds() const { return setup_seconds_; }

  /// Square operator on the owned dofs (known before the first compute: Thyra asks for it).
  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  void set_map(const Teuchos::RCP<const Map>& map) { map_ = map; }

  /// Applies the package's operator built by compute() (the direct solve overrides this).
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    built_->apply(X, Y, mode, alpha, beta);
  }

 protected:
  double setup_seconds_ = 0;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<Tpetra::Operator<>> built_;  ///< set by compute() of package preconditioners
};

/// The matrix the auxiliary-space multigrid is built on, from the Jacobian K (its rows and
/// maps): operators/AuxiliaryStiffness. Empty: K itself.
using AuxiliaryMatrix =
    std::function<Teuchos::RCP<const Tpetra::CrsMatrix<>>(const Tpetra::CrsMatrix<>& K)>;

/// The saddle point of the mixed u-p parts' bulk excess (operators/BulkSplit.hpp): the Jacobian
/// relieved of it (A), this rank's cells, q = D_1 B x, y = C^T q, the Schur diagonal, D_1's
/// diagonal square-rooted (D^1/2, the pressure rows' scale), the collocation rows and their scale in A, the inner tolerance.
struct BulkSplit {
  AuxiliaryMatrix relieved;
  std::size_t cells = 0;
  std::function<void(const Tpetra::Vector<>& x, double* q)> pressures;
  std::function<void(const double* q, Tpetra::Vector<>& y)> forces;
  std::vector<double> schur, root_weights;
  std::vector<int> constrained_rows;  ///< collocation rows (owned, local), scaled in A by
  double row_factor = 1;              ///< row_factor
  double tolerance = 1e-13;           ///< of the inner GMRES, relative
};

/// The preconditioner of `plan`; `near_null_space` (the rigid-body modes) is used by multigrid,
/// `auxiliary` by the auxiliary-space multigrid, `bulk` by the bulk split.
Teuchos::RCP<MatrixPreconditioner> make_matrix_preconditioner(
    const LinearSolverPlan& plan, const Teuchos::RCP<const Tpetra::Map<>>& dofs,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, const AuxiliaryMatrix& auxiliary = {},
    const BulkSplit& bulk = {});

Teuchos::RCP<MatrixPreconditioner> make_direct_preconditioner(
    const Teuchos::ParameterList& settings);
Teuchos::RCP<MatrixPreconditioner> make_multigrid_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates);
/// Multigrid built once from the auxiliary matrix of the first Jacobian (the stage's), then
/// kept: the matrix does not depend on the state (solvers/AuxiliaryPreconditioner.cpp).
Teuchos::RCP<MatrixPreconditioner> make_auxiliary_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, AuxiliaryMatrix auxiliary);
/// K^-1 by GMRES on the saddle point of the bulk excess, block upper triangular preconditioned
/// with one multigrid cycle on A (solvers/BulkSplitPreconditioner.cpp).
Teuchos::RCP<MatrixPreconditioner> make_bulk_split_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, BulkSplit bulk);
Teuchos::RCP<MatrixPreconditioner> make_ifpack2_preconditioner(
    const Teuchos::ParameterList& settings);

}  // namespace efg
