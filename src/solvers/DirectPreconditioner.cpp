// The direct path: the whole Jacobian factored by Amesos2 (KLU2 by default: sparse LU with
// fill-reducing ordering, any nonsymmetric matrix). The symbolic factorization is done once per
// stage (the sparsity never changes), the numeric one per Newton iteration.
#include <Amesos2.hpp>
#include <Teuchos_Time.hpp>

#include "core/Errors.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

class DirectPreconditioner : public MatrixPreconditioner {
 public:
  explicit DirectPreconditioner(std::string solver) : solver_name_(std::move(solver)) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("direct factorization", true);
    try {
      if (solver_.is_null() || K.get() != matrix_.get()) {
        if (!Amesos2::query(solver_name_))
          throw InputError("preconditioner.solver: Amesos2 has no solver '" + solver_name_ + "'");
        solver_ = Amesos2::create<Matrix, MultiVector>(solver_name_, K);
        matrix_ = K;
        solver_->symbolicFactorization();
      }
      solver_->numericFactorization();
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw NumericalError(
          "the direct solver (Amesos2 " + solver_name_ +
          ") could not factor the Jacobian: it is singular. Candidates: a body or part that "
          "is not held against rigid motion (missing or too few essential conditions), "
          "particles with no neighbours, a material with zero stiffness. (" +
          e.what() + ")");
    }
    setup_seconds_ += clock.stop();
  }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    if (mode != Teuchos::NO_TRANS)
      throw std::logic_error("DirectPreconditioner: transpose solves are not supported");
    MultiVector Z(Y.getMap(), Y.getNumVectors());
    solver_->solve(Teuchos::ptrFromRef(Z), Teuchos::ptrFromRef(X));
    Y.update(alpha, Z, beta);
  }

 private:
  std::string solver_name_;
  Teuchos::RCP<const Matrix> matrix_;
  Teuchos::RCP<Amesos2::Solver<Matrix, MultiVector>> solver_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_direct_preconditioner(
    const Teuchos::ParameterList& settings) {
  return Teuchos::rcp(new DirectPreconditioner(
      settings.isParameter("solver") ? settings.get<std::string>("solver") : "KLU2"));
}

}  // namespace efg
