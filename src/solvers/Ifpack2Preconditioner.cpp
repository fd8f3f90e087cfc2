// Any Ifpack2 preconditioner by name (RILUK, ILUT, RELAXATION, SCHWARZ, ...), one per rank (a
// block-Jacobi combination across ranks, so iteration counts grow with the rank count).
#include <Ifpack2_Factory.hpp>
#include <Teuchos_Time.hpp>

#include "core/Errors.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

class Ifpack2Preconditioner : public MatrixPreconditioner {
 public:
  explicit Ifpack2Preconditioner(const Teuchos::ParameterList& settings) : settings_(settings) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("Ifpack2 setup", true);
    Teuchos::ParameterList list(settings_);
    const std::string type = list.get<std::string>("Prec Type", "RILUK");
    list.remove("Prec Type");
    try {
      if (prec_.is_null() || K.get() != matrix_.get()) {
        prec_ = Ifpack2::Factory::create<Matrix>(type, K);
        prec_->setParameters(list);
        prec_->initialize();
        matrix_ = K;
      }
      prec_->compute();
    } catch (const std::exception& e) {
      throw NumericalError("the Ifpack2 " + type +
                           " preconditioner could not be built from the Jacobian: " + e.what());
    }
    built_ = prec_;
    setup_seconds_ += clock.stop();
  }

 private:
  Teuchos::ParameterList settings_;
  Teuchos::RCP<const Matrix> matrix_;
  Teuchos::RCP<Ifpack2::Preconditioner<double, Map::local_ordinal_type, Map::global_ordinal_type,
                                       Map::node_type>>
      prec_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_ifpack2_preconditioner(
    const Teuchos::ParameterList& settings) {
  return Teuchos::rcp(new Ifpack2Preconditioner(settings));
}

}  // namespace efg
