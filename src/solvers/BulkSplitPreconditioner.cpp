// The iterative path for mixed u-p parts above nu = 1/4 (operators/BulkSplit.hpp): the condensed
// system K du = x solved through the saddle point of its bulk stiffness above kappa_0,
//   [ A          C^T D^1/2 ] [du]   [x]
//   [ D^1/2 B    -I        ] [p ] = [0],
// by GMRES, right-preconditioned block upper triangular:
//   z_p = -S^-1 x_p, S = diag(1 + kappa_1 / M_0);  z_u = A^-1 (x_u - C^T D^1/2 z_p),
// A^-1 one smoothed-aggregation cycle on A, the Jacobian at kappa_0 (compressible: multigrid
// converges there; on K itself it stalls as nu -> 1/2, its near kernel being every
// divergence-free field). Measured on Lame's cylinder (patch pressures, subcells, edges):
// 13-22 inner iterations per Newton step at nu = 0.3 and 21-36 at 0.4999 and 0.499999 (16 x 32
// to 64 x 128 cells; docs/mixed.md). The inner solve goes below the outer tolerance by the
// amplification of its pressure rows' residual (LinearSolverPlan), so the outer fixed point on
// K (x += M^-1 r, the inner solution added unscaled) takes one application. The log gives the
// inner count of every solve.
#include <BelosBlockGmresSolMgr.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_Time.hpp>

#include <algorithm>
#include <cstdio>

#include "core/Log.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

using MV = Tpetra::MultiVector<>;
using OP = Tpetra::Operator<>;
using Vec = Tpetra::Vector<>;

// A combined vector's two parts: the dofs (first, in the dof map's order), then the cells.
struct Blocks {
  Teuchos::RCP<const Tpetra::Map<>> dofs, combined;
  std::size_t n_dofs = 0, n_cells = 0;

  void split(const MV& X, std::size_t j, Vec& u, std::vector<double>& q) const {
    const auto x = X.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto v = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t i = 0; i < n_dofs; ++i) v(i, 0) = x(i, j);
    q.resize(n_cells);
    for (std::size_t c = 0; c < n_cells; ++c) q[c] = x(n_dofs + c, j);
  }
  void join(const Vec& u, const std::vector<double>& q, MV& Y, std::size_t j, double alpha,
            double beta) const {
    auto y = Y.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto v = u.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t i = 0; i < n_dofs; ++i)
      y(i, j) = (beta == 0.0 ? 0.0 : beta * y(i, j)) + alpha * v(i, 0);
    for (std::size_t c = 0; c < n_cells; ++c)
      y(n_dofs + c, j) = (beta == 0.0 ? 0.0 : beta * y(n_dofs + c, j)) + alpha * q[c];
  }
};

class SaddleOperator : public OP {
 public:
  SaddleOperator(const Blocks& blocks, const BulkSplit& bulk) : b_(blocks), bulk_(bulk) {}
  void set_matrix(const Teuchos::RCP<const Tpetra::CrsMatrix<>>& A) { A_ = A; }
  Teuchos::RCP<const Tpetra::Map<>> getDomainMap() const override { return b_.combined; }
  Teuchos::RCP<const Tpetra::Map<>> getRangeMap() const override { return b_.combined; }
  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    Vec u(b_.dofs), Au(b_.dofs), f(b_.dofs);
    std::vector<double> q, Bq(b_.n_cells), sq(b_.n_cells);
    for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
      b_.split(X, j, u, q);
      // sqrt-scaled: [A, C^T D^1/2; D^1/2 B, -I] (the condensed residual is r_u + C^T D^1/2 r_p)
      A_->apply(u, Au);
      for (std::size_t c = 0; c < b_.n_cells; ++c) sq[c] = bulk_.root_weights[c] * q[c];
      bulk_.forces(sq.data(), f);
      Au.update(1.0, f, 1.0);
      bulk_.pressures(u, Bq.data());  // D B u
      for (std::size_t c = 0; c < b_.n_cells; ++c) {
        const double r = bulk_.root_weights[c];
        Bq[c] = r > 0 ? Bq[c] / r - q[c] : -q[c];
      }
      b_.join(Au, Bq, Y, j, alpha, beta);
    }
  }

 private:
  const Blocks& b_;
  const BulkSplit& bulk_;
  Teuchos::RCP<const Tpetra::CrsMatrix<>> A_;
};

class TriangularPreconditioner : public OP {
 public:
  TriangularPreconditioner(const Blocks& blocks, const BulkSplit& bulk,
                           const Teuchos::RCP<MatrixPreconditioner>& multigrid)
      : b_(blocks), bulk_(bulk), multigrid_(multigrid) {}
  Teuchos::RCP<const Tpetra::Map<>> getDomainMap() const override { return b_.combined; }
  Teuchos::RCP<const Tpetra::Map<>> getRangeMap() const override { return b_.combined; }
  void apply(const MV& X, MV& Y, Teuchos::ETransp, double alpha, double beta) const override {
    Vec u(b_.dofs), z(b_.dofs), f(b_.dofs);
    std::vector<double> q, zq(b_.n_cells), sq(b_.n_cells);
    for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
      b_.split(X, j, u, q);
      // upper triangular: z_q = -S^-1 x_q, S = 1 + kappa_1 / M_0; z_u = A^-1 (x_u - C^T D^1/2 z_q)
      for (std::size_t c = 0; c < b_.n_cells; ++c) {
        const double r = bulk_.root_weights[c];
        zq[c] = r > 0 ? -q[c] / bulk_.schur[c] : -q[c];
        sq[c] = r * zq[c];
      }
      bulk_.forces(sq.data(), f);
      u.update(-1.0, f, 1.0);
      multigrid_->apply(u, z, Teuchos::NO_TRANS, 1.0, 0.0);
      b_.join(z, zq, Y, j, alpha, beta);
    }
  }

 private:
  const Blocks& b_;
  const BulkSplit& bulk_;
  Teuchos::RCP<MatrixPreconditioner> multigrid_;
};

class BulkSplitPreconditioner : public MatrixPreconditioner {
 public:
  BulkSplitPreconditioner(const Teuchos::ParameterList& settings,
                          const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
                          const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, BulkSplit bulk)
      : multigrid_(make_multigrid_preconditioner(settings, near_null_space, coordinates)),
        bulk_(std::move(bulk)) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("bulk split setup", true);
    if (blocks_.combined.is_null()) build_maps(*K);
    const auto A = bulk_.relieved(*K);
    multigrid_->compute(A);
    saddle_->set_matrix(A);
    setup_seconds_ += clock.stop();
  }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, double alpha,
             double beta) const override {
    MV rhs(blocks_.combined, X.getNumVectors()), sol(blocks_.combined, X.getNumVectors());
    {
      const auto x = X.getLocalViewHost(Tpetra::Access::ReadOnly);
      auto r = rhs.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
        for (std::size_t i = 0; i < blocks_.n_dofs + blocks_.n_cells; ++i)
          r(i, j) = i < blocks_.n_dofs ? x(i, j) : 0.0;
        for (int c : bulk_.constrained_rows)  // A's collocation rows are scaled
          r(static_cast<std::size_t>(c), j) *= bulk_.row_factor;
      }
    }
    sol.putScalar(0.0);
    auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(
        saddle_, Teuchos::rcpFromRef(sol), Teuchos::rcpFromRef(rhs)));
    problem->setRightPrec(triangular_);
    problem->setProblem();
    auto params = Teuchos::parameterList();
    params->set("Num Blocks", 200);
    params->set("Maximum Iterations", 1000);
    params->set("Convergence Tolerance", bulk_.tolerance);
    params->set("Verbosity", Belos::Errors);
    Belos::BlockGmresSolMgr<double, MV, OP> solver(problem, params);
    solver.solve();
    char line[160];
    std::snprintf(line, sizeof line,
                  "      saddle point: %d GMRES iterations, residual %.3e of its start",
                  solver.getNumIters(), solver.achievedTol());
    Log::info(line);
    auto y = Y.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto s = sol.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t j = 0; j < X.getNumVectors(); ++j)
      for (std::size_t i = 0; i < blocks_.n_dofs; ++i)
        y(i, j) = (beta == 0.0 ? 0.0 : beta * y(i, j)) + alpha * s(i, j);
  }

 private:
  void build_maps(const Matrix& K) {
    blocks_.dofs = K.getRowMap();
    blocks_.n_dofs = blocks_.dofs->getNodeNumElements();
    blocks_.n_cells = bulk_.cells;
    const auto comm = blocks_.dofs->getComm();
    long long mine = static_cast<long long>(blocks_.n_cells), before = 0;
    Teuchos::scan(*comm, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(before));
    before -= mine;
    std::vector<Tpetra::Map<>::global_ordinal_type> gids;
    gids.reserve(blocks_.n_dofs + blocks_.n_cells);
    for (std::size_t i = 0; i < blocks_.n_dofs; ++i)
      gids.push_back(blocks_.dofs->getGlobalElement(static_cast<int>(i)));
    const auto first_cell = blocks_.dofs->getMaxAllGlobalIndex() + 1;
    for (std::size_t c = 0; c < blocks_.n_cells; ++c)
      gids.push_back(first_cell + before + static_cast<long long>(c));
    blocks_.combined = Teuchos::rcp(new Tpetra::Map<>(
        Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
        Teuchos::ArrayView<const Tpetra::Map<>::global_ordinal_type>(gids), 0, comm));
    saddle_ = Teuchos::rcp(new SaddleOperator(blocks_, bulk_));
    triangular_ = Teuchos::rcp(new TriangularPreconditioner(blocks_, bulk_, multigrid_));
  }

  Teuchos::RCP<MatrixPreconditioner> multigrid_;
  BulkSplit bulk_;
  Blocks blocks_;
  Teuchos::RCP<SaddleOperator> saddle_;
  Teuchos::RCP<TriangularPreconditioner> triangular_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_bulk_split_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, BulkSplit bulk) {
  return Teuchos::rcp(
      new BulkSplitPreconditioner(settings, near_null_space, coordinates, std::move(bulk)));
}

}  // namespace efg
