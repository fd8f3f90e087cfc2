#include "solvers/MatrixPreconditioner.hpp"

namespace efg {

Teuchos::RCP<MatrixPreconditioner> make_matrix_preconditioner(
    const LinearSolverPlan& plan, const Teuchos::RCP<const Tpetra::Map<>>& dofs,
    const Teuchos::RCP<Tpetra::MultiVector<>>& near_null_space,
    const Teuchos::RCP<Tpetra::MultiVector<>>& coordinates, const AuxiliaryMatrix& auxiliary,
    const BulkSplit& bulk) {
  using P = LinearSolverPlan::Preconditioner;
  Teuchos::RCP<MatrixPreconditioner> p;
  switch (plan.preconditioner) {
    case P::direct:
      p = make_direct_preconditioner(plan.settings);
      break;
    case P::multigrid:
      p = make_multigrid_preconditioner(plan.settings, near_null_space, coordinates);
      break;
    case P::auxiliary:
      p = make_auxiliary_preconditioner(plan.settings, near_null_space, coordinates, auxiliary);
      break;
    case P::bulk_split:
      p = make_bulk_split_preconditioner(plan.settings, near_null_space, coordinates, bulk);
      break;
    case P::ifpack2:
      p = make_ifpack2_preconditioner(plan.settings);
      break;
    case P::none:
      break;
  }
  if (!p.is_null()) p->set_map(dofs);
  return p;
}

}  // namespace efg
