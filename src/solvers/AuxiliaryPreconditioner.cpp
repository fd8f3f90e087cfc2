// The auxiliary-space preconditioner (operators/AuxiliaryStiffness.hpp): smoothed-aggregation
// multigrid (the multigrid path's MueLu settings, with the rigid-body modes) built on a finite
// element matrix of the background cells instead of the meshfree Jacobian. The matrix depends on
// the reference configuration and the elastic moduli only, so the hierarchy is built once, from
// the stage's first Jacobian, and kept for every Newton iteration and load step after it (a
// tangent that softens - plasticity, large rotations - costs Krylov iterations, not setups).
#include <Teuchos_Time.hpp>

#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

class AuxiliaryPreconditioner : public MatrixPreconditioner {
 public:
  AuxiliaryPreconditioner(const Teuchos::ParameterList& settings,
                          const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
                          const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates,
                          AuxiliaryMatrix auxiliary)
      : multigrid_(make_multigrid_preconditioner(settings, near_null_space, coordinates)),
        auxiliary_(std::move(auxiliary)) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    if (built_once_) return;
    Teuchos::Time clock("auxiliary setup", true);
    const auto A = auxiliary_ ? auxiliary_(*K) : K;
    multigrid_->compute(A);
    built_once_ = true;
    setup_seconds_ += clock.stop();
  }

  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode, double alpha,
             double beta) const override {
    multigrid_->apply(X, Y, mode, alpha, beta);
  }

 private:
  Teuchos::RCP<MatrixPreconditioner> multigrid_;
  AuxiliaryMatrix auxiliary_;
  bool built_once_ = false;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_auxiliary_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, AuxiliaryMatrix auxiliary) {
  return Teuchos::rcp(
      new AuxiliaryPreconditioner(settings, near_null_space, coordinates, std::move(auxiliary)));
}

}  // namespace efg
