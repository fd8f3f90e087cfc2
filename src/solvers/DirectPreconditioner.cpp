// The direct path: the whole Jacobian factored by Amesos2 KLU2 (sparse LU with a fill-reducing
// ordering; any nonsymmetric matrix). On more than one rank the matrix is gathered onto rank 0
// and factored there on a one-process communicator, because Amesos2 KLU2 in Trilinos 13.2
// returns wrong solutions when it is handed a distributed matrix (toolchain.md); right-hand
// sides are gathered, solved on rank 0 and scattered back. So every rank count gets the same
// factorization, at the cost of one process's time and memory: the automatic choice uses it
// only below a size limit (LinearSolverPlan).
#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <vector>

#include "core/Errors.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

using GO = Tpetra::Map<>::global_ordinal_type;
using LO = Tpetra::Map<>::local_ordinal_type;

/// The same global ids as `distributed`, all on rank 0, ascending.
Teuchos::RCP<const Tpetra::Map<>> root_map(const Tpetra::Map<>& distributed) {
  const auto& comm = *distributed.getComm();
  const auto mine = distributed.getNodeElementList();
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(comm.getSize()), 0);
  Teuchos::gatherAll(comm, 1, &count, comm.getSize(), counts.data());
  std::vector<int> offsets(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<GO> all(comm.getRank() == 0 ? distributed.getGlobalNumElements() : 0);
  Teuchos::gatherv(mine.getRawPtr(), count, all.data(), counts.data(), offsets.data(), 0, comm);
  // Ascending ids: the factored matrix has the same row order (so the same pivot order and
  // round-off) on any rank count.
  std::sort(all.begin(), all.end());
  return Teuchos::rcp(new Tpetra::Map<>(distributed.getGlobalNumElements(), all.data(),
                                        static_cast<LO>(all.size()), distributed.getIndexBase(),
                                        distributed.getComm()));
}

class DirectPreconditioner : public MatrixPreconditioner {
 public:
  explicit DirectPreconditioner(std::string solver) : solver_name_(std::move(solver)) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("direct factorization", true);
    if (root_.is_null()) {
      root_ = root_map(*K->getRowMap());
      gather_ = Teuchos::rcp(new Tpetra::Import<>(K->getRowMap(), root_));
      scatter_ = Teuchos::rcp(new Tpetra::Import<>(root_, K->getRowMap()));
    }
    // Gather the rows onto rank 0 ...
    Matrix gathered(root_, 0);
    gathered.doImport(*K, *gather_, Tpetra::INSERT);
    gathered.fillComplete(root_, root_);
    // ... and copy them into a matrix of rank 0's own (a one-process communicator).
    int failed = 0;
    std::string why;
    if (root_->getComm()->getRank() == 0) {
      try {
        factor(gathered);
      } catch (const std::exception& e) {
        failed = 1;
        why = e.what();
      }
    }
    Teuchos::broadcast(*root_->getComm(), 0, Teuchos::outArg(failed));
    if (failed)
      throw NumericalError(
          "the direct solver (Amesos2 " + solver_name_ +
          ") could not factor the Jacobian: it is singular. Candidates: a body or part that "
          "is not held against rigid motion (missing or too few essential conditions), "
          "particles with no neighbours, a material with zero stiffness" +
          (why.empty() ? std::string(".") : " (" + why + ")."));
    setup_seconds_ += clock.stop();
  }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    if (mode != Teuchos::NO_TRANS)
      throw std::logic_error("DirectPreconditioner: transpose solves are not supported");
    const auto n = X.getNumVectors();
    MultiVector x_root(root_, n), z_root(root_, n);
    x_root.doImport(X, *gather_, Tpetra::INSERT);
    if (root_->getComm()->getRank() == 0) {
      MultiVector x_serial(serial_map_, n), z_serial(serial_map_, n);
      Kokkos::deep_copy(x_serial.getLocalViewHost(Tpetra::Access::OverwriteAll),
                        x_root.getLocalViewHost(Tpetra::Access::ReadOnly));
      solver_->solve(Teuchos::ptrFromRef(z_serial), Teuchos::ptrFromRef(x_serial));
      Kokkos::deep_copy(z_root.getLocalViewHost(Tpetra::Access::OverwriteAll),
                        z_serial.getLocalViewHost(Tpetra::Access::ReadOnly));
    }
    MultiVector z(Y.getMap(), n);
    z.doImport(z_root, *scatter_, Tpetra::INSERT);
    Y.update(alpha, z, beta);
  }

 private:
  // Rank 0: copies the gathered rows (global ids) into the one-process matrix and factors it;
  // the symbolic factorization is kept while the sparsity stays the same.
  void factor(const Matrix& gathered) {
    if (serial_map_.is_null()) {
      auto self = Teuchos::createSerialComm<int>();
      const auto gids = root_->getNodeElementList();
      serial_map_ = Teuchos::rcp(
          new Tpetra::Map<>(root_->getGlobalNumElements(), gids, root_->getIndexBase(), self));
    }
    const auto rows = static_cast<std::size_t>(gathered.getNodeNumRows());
    auto serial = Teuchos::rcp(new Matrix(serial_map_, gathered.getNodeMaxNumRowEntries()));
    typename Matrix::nonconst_global_inds_host_view_type cols("cols",
                                                              gathered.getNodeMaxNumRowEntries());
    typename Matrix::nonconst_values_host_view_type vals("vals",
                                                         gathered.getNodeMaxNumRowEntries());
    const auto gids = root_->getNodeElementList();
    for (std::size_t i = 0; i < rows; ++i) {
      std::size_t count = 0;
      gathered.getGlobalRowCopy(gids[i], cols, vals, count);
      serial->insertGlobalValues(gids[i], static_cast<LO>(count), vals.data(), cols.data());
    }
    serial->fillComplete(serial_map_, serial_map_);
    const bool same_pattern = !solver_.is_null() && !serial_matrix_.is_null() &&
                              serial_matrix_->getNodeNumEntries() == serial->getNodeNumEntries();
    serial_matrix_ = serial;
    if (solver_.is_null()) {
      solver_ = Amesos2::create<Matrix, MultiVector>(solver_name_, serial_matrix_);
      solver_->symbolicFactorization();
    } else {
      solver_->setA(serial_matrix_, same_pattern ? Amesos2::SYMBFACT : Amesos2::CLEAN);
      if (!same_pattern) solver_->symbolicFactorization();
    }
    solver_->numericFactorization();
  }

  std::string solver_name_;
  Teuchos::RCP<const Tpetra::Map<>> root_, serial_map_;
  Teuchos::RCP<Tpetra::Import<>> gather_, scatter_;
  Teuchos::RCP<Matrix> serial_matrix_;
  Teuchos::RCP<Amesos2::Solver<Matrix, MultiVector>> solver_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_direct_preconditioner(
    const Teuchos::ParameterList& settings) {
  return Teuchos::rcp(new DirectPreconditioner(
      settings.isParameter("solver") ? settings.get<std::string>("solver") : "KLU2"));
}

}  // namespace efg
