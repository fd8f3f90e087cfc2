// The direct path: the whole Jacobian factored by a sparse LU: MUMPS (multifrontal, BLAS 3, all
// processes factor together; solvers/DistributedLU), UMFPACK (multifrontal, one process) or
// Amesos2 KLU2 (left-looking; kept as an option). UMFPACK and KLU2 get the matrix gathered onto
// rank 0 and factor it there on one process, because Amesos2 KLU2 in Trilinos 13.2 returns wrong
// solutions when it is handed a distributed matrix (toolchain.md) and UMFPACK is a one-process
// library; MUMPS reads each rank's rows where they are. Right-hand sides are gathered, solved on
// rank 0 (MUMPS: by all ranks, from rank 0's copy) and scattered back.
#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_Time.hpp>
#include <Tpetra_Import.hpp>

#include <algorithm>
#include <memory>
#include <vector>

#include "core/Errors.hpp"
#include "solvers/DistributedLU.hpp"
#include "solvers/MatrixPreconditioner.hpp"
#include "solvers/SparseLU.hpp"

namespace efg {
namespace {

using GO = Tpetra::Map<>::global_ordinal_type;
using LO = Tpetra::Map<>::local_ordinal_type;
using Matrix = Tpetra::CrsMatrix<>;
using MultiVector = Tpetra::MultiVector<>;

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

// What factors the gathered matrix on rank 0 and solves with it there.
class RootSolver {
 public:
  virtual ~RootSolver() = default;
  /// `whole`: a matrix whose rows are all on this process (rank 0); `root` holds the same ids,
  /// ascending, and sets the order of rows and columns in the factorization.
  virtual void factor(const Matrix& whole, const Tpetra::Map<>& root) = 0;
  /// z = A^-1 x for the vectors of x (on rank 0, root map).
  virtual void solve(const MultiVector& x, MultiVector& z) const = 0;
};

// UMFPACK (solvers/SparseLU.hpp) on the rows of a matrix held whole by this process, each row
// and column placed at its position in `root` (ascending ids), so the factored matrix is the same
// whatever the row order the matrix came in.
class UmfpackRootSolver : public RootSolver {
 public:
  void factor(const Matrix& whole, const Tpetra::Map<>& root) override {
    const auto local = whole.getLocalMatrixHost();
    const auto& rows = *whole.getRowMap();
    const auto& columns = *whole.getColMap();
    std::vector<std::int64_t> column_position(columns.getNodeNumElements());
    for (std::size_t c = 0; c < column_position.size(); ++c)
      column_position[c] = root.getLocalElement(columns.getGlobalElement(static_cast<LO>(c)));
    const auto n = static_cast<std::int64_t>(local.numRows());
    std::vector<std::int64_t> row_position(static_cast<std::size_t>(n));
    std::vector<std::int64_t> start(static_cast<std::size_t>(n) + 1, 0), index(local.nnz());
    std::vector<double> value(local.nnz());
    for (std::int64_t i = 0; i < n; ++i) {
      row_position[i] = root.getLocalElement(rows.getGlobalElement(static_cast<LO>(i)));
      start[row_position[i] + 1] =
          static_cast<std::int64_t>(local.graph.row_map(i + 1) - local.graph.row_map(i));
    }
    for (std::int64_t i = 0; i < n; ++i) start[i + 1] += start[i];
    for (std::int64_t i = 0; i < n; ++i) {
      auto k = start[row_position[i]];
      for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e, ++k) {
        index[k] = column_position[static_cast<std::size_t>(local.graph.entries(e))];
        value[k] = local.values(e);
      }
    }
    lu_.factor(n, std::move(start), std::move(index), std::move(value));
  }

  void solve(const MultiVector& x, MultiVector& z) const override {
    const auto xv = x.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto zv = z.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t j = 0; j < x.getNumVectors(); ++j) lu_.solve(&xv(0, j), &zv(0, j));
  }

 private:
  SparseLU lu_;
};

// Amesos2 (KLU2) on a copy of the gathered rows with a one-process communicator.
class Amesos2RootSolver : public RootSolver {
 public:
  explicit Amesos2RootSolver(std::string name) : name_(std::move(name)) {}

  // The symbolic factorization is kept while the sparsity stays the same.
  void factor(const Matrix& whole, const Tpetra::Map<>& root) override {
    const auto gids = root.getNodeElementList();
    if (serial_map_.is_null())
      serial_map_ =
          Teuchos::rcp(new Tpetra::Map<>(root.getGlobalNumElements(), gids, root.getIndexBase(),
                                         Teuchos::createSerialComm<int>()));
    const auto rows = static_cast<std::size_t>(whole.getNodeNumRows());
    const auto widest = whole.getNodeMaxNumRowEntries();
    auto serial = Teuchos::rcp(new Matrix(serial_map_, widest));
    typename Matrix::nonconst_global_inds_host_view_type cols("cols", widest);
    typename Matrix::nonconst_values_host_view_type vals("vals", widest);
    for (std::size_t i = 0; i < rows; ++i) {
      std::size_t count = 0;
      whole.getGlobalRowCopy(gids[i], cols, vals, count);
      serial->insertGlobalValues(gids[i], static_cast<LO>(count), vals.data(), cols.data());
    }
    serial->fillComplete(serial_map_, serial_map_);
    const bool same_pattern = !solver_.is_null() && !matrix_.is_null() &&
                              matrix_->getNodeNumEntries() == serial->getNodeNumEntries();
    matrix_ = serial;
    if (solver_.is_null()) {
      solver_ = Amesos2::create<Matrix, MultiVector>(name_, matrix_);
      solver_->symbolicFactorization();
    } else {
      solver_->setA(matrix_, same_pattern ? Amesos2::SYMBFACT : Amesos2::CLEAN);
      if (!same_pattern) solver_->symbolicFactorization();
    }
    solver_->numericFactorization();
  }

  void solve(const MultiVector& x, MultiVector& z) const override {
    const auto n = x.getNumVectors();
    MultiVector x_serial(serial_map_, n), z_serial(serial_map_, n);
    Kokkos::deep_copy(x_serial.getLocalViewHost(Tpetra::Access::OverwriteAll),
                      x.getLocalViewHost(Tpetra::Access::ReadOnly));
    solver_->solve(Teuchos::ptrFromRef(z_serial), Teuchos::ptrFromRef(x_serial));
    Kokkos::deep_copy(z.getLocalViewHost(Tpetra::Access::OverwriteAll),
                      z_serial.getLocalViewHost(Tpetra::Access::ReadOnly));
  }

 private:
  std::string name_;
  Teuchos::RCP<const Tpetra::Map<>> serial_map_;
  Teuchos::RCP<Matrix> matrix_;
  Teuchos::RCP<Amesos2::Solver<Matrix, MultiVector>> solver_;
};

// MUMPS on the rows each rank owns: positions are the global ids less the smallest (the dof maps
// number 0 .. n-1 without gaps; checked), which is also the order of the root map.
class MumpsSolver {
 public:
  explicit MumpsSolver(const Teuchos::Comm<int>& comm) : lu_(raw_comm(comm)) {}

  void factor(const Matrix& K) {
    const auto& map = *K.getRowMap();
    const GO first = map.getMinAllGlobalIndex(), last = map.getMaxAllGlobalIndex();
    if (last - first + 1 != static_cast<GO>(map.getGlobalNumElements()))
      throw std::logic_error("MumpsSolver: the row ids have gaps");
    const auto local = K.getLocalMatrixHost();
    const auto& columns = *K.getColMap();
    std::vector<int> rows(local.nnz()), cols(local.nnz());
    std::vector<double> values(local.nnz());
    for (LO i = 0; i < static_cast<LO>(local.numRows()); ++i) {
      const auto row = static_cast<int>(map.getGlobalElement(i) - first);
      for (auto e = local.graph.row_map(i); e < local.graph.row_map(i + 1); ++e) {
        rows[e] = row;
        cols[e] = static_cast<int>(columns.getGlobalElement(local.graph.entries(e)) - first);
        values[e] = local.values(e);
      }
    }
    lu_.factor(static_cast<std::int64_t>(map.getGlobalNumElements()), std::move(rows),
               std::move(cols), std::move(values));
  }

  /// z = A^-1 x: x and z on the root map (all on rank 0); every rank calls.
  void solve(const MultiVector& x, MultiVector& z) {
    const auto n = static_cast<int>(x.getNumVectors());
    Tpetra::deep_copy(z, x);
    auto zv = z.getLocalViewHost(Tpetra::Access::ReadWrite);
    const bool root = x.getMap()->getComm()->getRank() == 0;
    if (root && zv.stride(1) != zv.extent(0) && n > 1)
      throw std::logic_error("MumpsSolver: the vectors are not stored one after another");
    lu_.solve(root ? zv.data() : nullptr, n);
  }

 private:
  static MPI_Comm raw_comm(const Teuchos::Comm<int>& comm) {
    const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
    return mpi ? (*mpi->getRawMpiComm())() : MPI_COMM_SELF;
  }
  DistributedLU lu_;
};

class DirectPreconditioner : public MatrixPreconditioner {
 public:
  explicit DirectPreconditioner(std::string solver) : solver_name_(std::move(solver)) {
    if (solver_name_ == "MUMPS") return;  // built with the first matrix (its communicator)
    if (solver_name_ == "UMFPACK")
      root_solver_ = std::make_unique<UmfpackRootSolver>();
    else
      root_solver_ = std::make_unique<Amesos2RootSolver>(solver_name_);
  }

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("direct factorization", true);
    if (root_.is_null()) {
      root_ = root_map(*K->getRowMap());
      gather_ = Teuchos::rcp(new Tpetra::Import<>(K->getRowMap(), root_));
      scatter_ = Teuchos::rcp(new Tpetra::Import<>(root_, K->getRowMap()));
    }
    if (solver_name_ == "MUMPS") {
      factor_distributed(*K);
      setup_seconds_ += clock.stop();
      return;
    }
    // Gather the rows onto rank 0 (one rank: K is whole already) and factor them there.
    Teuchos::RCP<const Matrix> whole = K;
    if (root_->getComm()->getSize() > 1) {
      auto gathered = Teuchos::rcp(new Matrix(root_, 0));
      gathered->doImport(*K, *gather_, Tpetra::INSERT);
      gathered->fillComplete(root_, root_);
      whole = gathered;
    }
    int failed = 0;
    std::string why;
    if (root_->getComm()->getRank() == 0) {
      try {
        root_solver_->factor(*whole, *root_);
      } catch (const std::exception& e) {
        failed = 1;
        why = e.what();
      }
    }
    Teuchos::broadcast(*root_->getComm(), 0, Teuchos::outArg(failed));
    if (failed) singular(why);
    setup_seconds_ += clock.stop();
  }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    if (mode != Teuchos::NO_TRANS)
      throw std::logic_error("DirectPreconditioner: transpose solves are not supported");
    const auto n = X.getNumVectors();
    MultiVector x_root(root_, n), z_root(root_, n);
    x_root.doImport(X, *gather_, Tpetra::INSERT);
    if (mumps_)
      mumps_->solve(x_root, z_root);
    else if (root_->getComm()->getRank() == 0)
      root_solver_->solve(x_root, z_root);
    MultiVector z(Y.getMap(), n);
    z.doImport(z_root, *scatter_, Tpetra::INSERT);
    Y.update(alpha, z, beta);
  }

 private:
  [[noreturn]] void singular(const std::string& why) const {
    throw NumericalError(
        "the direct solver (" + solver_name_ +
        ") could not factor the Jacobian: it is singular. Candidates: a body or part that "
        "is not held against rigid motion (missing or too few essential conditions), "
        "particles with no neighbours, a material with zero stiffness" +
        (why.empty() ? std::string(".") : " (" + why + ")."));
  }

  void factor_distributed(const Matrix& K) {
    if (!mumps_) mumps_ = std::make_unique<MumpsSolver>(*K.getRowMap()->getComm());
    // MUMPS throws on every rank alike (its status is global).
    try {
      mumps_->factor(K);
    } catch (const SingularMatrixError& e) {
      singular(e.what());
    } catch (const std::runtime_error& e) {
      throw NumericalError(
          "the direct solver (MUMPS) could not factor the Jacobian: " + std::string(e.what()) +
          " (a smaller model, more ranks, or solver: iterative)");
    }
  }

  std::string solver_name_;
  std::unique_ptr<RootSolver> root_solver_;
  std::unique_ptr<MumpsSolver> mumps_;
  Teuchos::RCP<const Tpetra::Map<>> root_;
  Teuchos::RCP<Tpetra::Import<>> gather_, scatter_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_direct_preconditioner(
    const Teuchos::ParameterList& settings) {
  // (efg check builds this on a small matrix: a misspelt key is bad input, not ignored.)
  for (auto it = settings.begin(); it != settings.end(); ++it)
    if (settings.name(it) != "solver")
      throw std::invalid_argument("'" + settings.name(it) +
                                  "' is not a parameter of the direct solver (it takes 'solver')");
  return Teuchos::rcp(new DirectPreconditioner(
      settings.isParameter("solver") ? settings.get<std::string>("solver") : "MUMPS"));
}

}  // namespace efg
