// The scalable path: smoothed-aggregation algebraic multigrid (MueLu) with the rigid-body modes
// as near-null space, so that the coarse spaces carry translations and rotations exactly and the
// iteration count stays nearly flat under refinement. The hierarchy is rebuilt for every new
// Jacobian (its values change with the state).
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Teuchos_Time.hpp>

#include "core/Errors.hpp"
#include "solvers/MatrixPreconditioner.hpp"

namespace efg {
namespace {

class MultigridPreconditioner : public MatrixPreconditioner {
 public:
  MultigridPreconditioner(const Teuchos::ParameterList& settings,
                          Teuchos::RCP<Tpetra::MultiVector<>> near_null_space,
                          Teuchos::RCP<Tpetra::MultiVector<>> coordinates)
      : settings_(settings),
        near_null_space_(std::move(near_null_space)),
        coordinates_(std::move(coordinates)) {}

  void compute(const Teuchos::RCP<const Matrix>& K) override {
    Teuchos::Time clock("multigrid setup", true);
    Teuchos::ParameterList list(settings_);
    if (!near_null_space_.is_null()) list.sublist("user data").set("Nullspace", near_null_space_);
    if (!coordinates_.is_null()) list.sublist("user data").set("Coordinates", coordinates_);
    try {
      auto op = Teuchos::rcp_const_cast<Matrix>(K);
      hierarchy_ = MueLu::CreateTpetraPreconditioner<double, Map::local_ordinal_type,
                                                     Map::global_ordinal_type, Map::node_type>(
          Teuchos::RCP<Tpetra::Operator<>>(op), list);
    } catch (const std::exception& e) {
      throw NumericalError(std::string("the multigrid preconditioner (MueLu) could not be built "
                                       "from the Jacobian: ") +
                           e.what());
    }
    built_ = hierarchy_;
    setup_seconds_ += clock.stop();
  }

 private:
  Teuchos::ParameterList settings_;
  Teuchos::RCP<Tpetra::MultiVector<>> near_null_space_, coordinates_;
  Teuchos::RCP<Tpetra::Operator<>> hierarchy_;
};

}  // namespace

Teuchos::RCP<MatrixPreconditioner> make_multigrid_preconditioner(
    const Teuchos::ParameterList& settings,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates) {
  return Teuchos::rcp(new MultigridPreconditioner(settings, near_null_space, coordinates));
}

}  // namespace efg
