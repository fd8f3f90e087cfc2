#include "drivers/SolidModelEvaluator.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <limits>

#include "core/Errors.hpp"
#include "parallel/Collective.hpp"

namespace efg {
namespace {
using Extract = Thyra::TpetraOperatorVectorExtraction<double, Map::local_ordinal_type,
                                                      GlobalOrdinal, Map::node_type>;
}

SolidModelEvaluator::SolidModelEvaluator(NonlinearProblem& problem, const Vector& initial_guess)
    : problem_(problem), space_(Thyra::createVectorSpace<double>(problem.owned_dofs())) {
  set_initial_guess(initial_guess);
}

void SolidModelEvaluator::set_initial_guess(const Vector& guess) {
  auto x0 = Teuchos::rcp(new Vector(guess, Teuchos::Copy));
  Thyra::ModelEvaluatorBase::InArgsSetup<double> nominal = createInArgs();
  nominal.set_x(Thyra::createVector(Teuchos::rcp_implicit_cast<Tpetra::Vector<>>(x0), space_));
  nominal_ = nominal;
}

Thyra::ModelEvaluatorBase::InArgs<double> SolidModelEvaluator::createInArgs() const {
  Thyra::ModelEvaluatorBase::InArgsSetup<double> in;
  in.setModelEvalDescription(this->description());
  in.setSupports(Thyra::ModelEvaluatorBase::IN_ARG_x);
  return std::move(in);
}

Thyra::ModelEvaluatorBase::OutArgs<double> SolidModelEvaluator::createOutArgsImpl() const {
  Thyra::ModelEvaluatorBase::OutArgsSetup<double> out;
  out.setModelEvalDescription(this->description());
  out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_f);
  out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_W_op);
  if (!preconditioner_.is_null()) out.setSupports(Thyra::ModelEvaluatorBase::OUT_ARG_W_prec);
  return std::move(out);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> SolidModelEvaluator::create_W_op() const {
  auto K = problem_.create_matrix();
  K->beginAssembly();  // leave it fill-complete in owned mode, as Thyra expects
  K->endAssembly();
  Teuchos::RCP<Tpetra::Operator<>> op = K;
  return Thyra::createLinearOp<double>(op, space_, space_);
}

Teuchos::RCP<Thyra::PreconditionerBase<double>> SolidModelEvaluator::create_W_prec() const {
  if (preconditioner_.is_null()) return Teuchos::null;
  Teuchos::RCP<Tpetra::Operator<>> op = preconditioner_;
  return Teuchos::rcp(
      new Thyra::DefaultPreconditioner<double>(Thyra::createLinearOp<double>(op, space_, space_)));
}

double SolidModelEvaluator::linear_residual_ratio(const Thyra::VectorBase<double>& dd,
                                                  const Thyra::VectorBase<double>& r) const {
  if (last_jacobian_.is_null()) return -1;
  const auto d = Extract::getConstTpetraVector(Teuchos::rcpFromRef(dd));
  const auto f = Extract::getConstTpetraVector(Teuchos::rcpFromRef(r));
  Vector jd(f->getMap());
  last_jacobian_->apply(*d, jd);
  const double rn = f->norm2();
  jd.update(1.0, *f, 1.0);
  return rn > 0 ? jd.norm2() / rn : 0.0;
}

void SolidModelEvaluator::evalModelImpl(
    const Thyra::ModelEvaluatorBase::InArgs<double>& in,
    const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const {
  const auto x = Extract::getConstTpetraVector(in.get_x());
  const auto f_thyra = out.get_f();
  const auto w_thyra = out.get_W_op();
  int failed = 0;
  try {
    if (!f_thyra.is_null()) problem_.residual(*x, *Extract::getTpetraVector(f_thyra));
    if (!w_thyra.is_null()) {
      last_jacobian_ =
          Teuchos::rcp_dynamic_cast<FEMatrix>(Extract::getTpetraOperator(w_thyra), true);
      problem_.jacobian(*x, *last_jacobian_);
    }
  } catch (const NumericalError& e) {
    failure_ = e.what();
    failed = 1;
  } catch (const PeerFailure& e) {  // the evaluation failed on another rank (agreed collectively)
    if (e.exit_code() != static_cast<int>(ExitCode::numerical)) throw;
    failure_ = e.what();
    failed = 1;
  }
  int any = 0;
  Teuchos::reduceAll(*problem_.owned_dofs()->getComm(), Teuchos::REDUCE_MAX, failed,
                     Teuchos::outArg(any));
  // The preconditioner is built from the Jacobian NOX evaluated last (NOX asks for W_prec right
  // after W_op, before the linear solve), on every rank or none (MUMPS factors collectively). A
  // singular factorization is no failure of the evaluation point but of the linear system: it
  // propagates as a NumericalError.
  // A linear problem (small-strain linear elastic, no contact) keeps its first factorization:
  // when round-off makes Newton take a second iteration (a nearly incompressible block at
  // nu = 0.4999, 33,516 dofs: 16 s per MUMPS factorization), or over the stage's load steps.
  if (!any && out.supports(Thyra::ModelEvaluatorBase::OUT_ARG_W_prec) &&
      !out.get_W_prec().is_null() && !preconditioner_.is_null() && !last_jacobian_.is_null() &&
      !(problem_.linear() && computed_for_linear_)) {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: linear solver setup"));
    preconditioner_->compute(last_jacobian_);
    computed_for_linear_ = problem_.linear();
  }
  if (any && !f_thyra.is_null())
    Thyra::assign(f_thyra.ptr(), std::numeric_limits<double>::quiet_NaN());
  if (any && failure_.empty()) failure_ = "numerical failure on another rank";
}

}  // namespace efg
