// The Thyra model evaluator NOX drives: x = generalized particle displacements (owned dofs),
// f = the residual of a NonlinearProblem (solids or shells), W = its Jacobian (an FECrsMatrix on the fixed graph).
// NOX has no Tpetra group in Trilinos 13.2; this is the documented path through Thyra.
#pragma once

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include <string>

#include "drivers/NonlinearProblem.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {

class SolidModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
 public:
  SolidModelEvaluator(NonlinearProblem& problem, const Vector& initial_guess);

  void set_W_factory(
      const Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>>& factory) {
    w_factory_ = factory;
  }
  void set_initial_guess(const Vector& guess);
  /// The preconditioner rebuilt from every new Jacobian (W_prec); none: Belos runs without one.
  void set_preconditioner(const Teuchos::RCP<MatrixPreconditioner>& preconditioner) {
    preconditioner_ = preconditioner;
  }

  /// The message of the last numerical failure inside an evaluation (empty when none). Such a
  /// failure (e.g. an inverted point) turns the residual into NaN on every rank, so that NOX's
  /// finite-value test stops the step collectively and the driver can cut the step back.
  const std::string& failure() const { return failure_; }
  /// ||J dd + r|| / ||r|| with the Jacobian evaluated last (the achieved linear reduction).
  double linear_residual_ratio(const Thyra::VectorBase<double>& dd,
                               const Thyra::VectorBase<double>& r) const;
  void clear_failure() { failure_.clear(); }

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override { return space_; }
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override { return nominal_; }
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override {
    return w_factory_;
  }
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<Thyra::PreconditionerBase<double>> create_W_prec() const override;

 protected:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const override;

 private:
  NonlinearProblem& problem_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> w_factory_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_;
  Teuchos::RCP<MatrixPreconditioner> preconditioner_;
  /// A linear problem's Jacobian is the same at every d: its first factorization (or multigrid
  /// hierarchy) serves every later solve of the stage.
  mutable bool computed_for_linear_ = false;
  mutable Teuchos::RCP<FEMatrix> last_jacobian_;  ///< the W_op evaluated last (W_prec's source)
  mutable std::string failure_;
};

}  // namespace efg
