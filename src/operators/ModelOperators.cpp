#include "operators/ModelOperators.hpp"

#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"

namespace efg {
namespace {
std::unique_ptr<ExactSolution> exact_of(const Model& model) {
  if (model.scene.exact_solution.empty()) return nullptr;
  return std::make_unique<ExactSolution>(make_exact_solution(model.scene, model.mesh.dimension));
}
}  // namespace

ModelOperators::ModelOperators(const Model& model)
    : model_(model),
      exact_(exact_of(model)),
      solid_(model),
      mixed_(MixedPressure::build(model, solid_)),
      loads_(model, solid_, exact_.get()),
      import_(Teuchos::rcp(new Tpetra::Import<>(model.maps.owned_dofs, model.maps.overlap_dofs))),
      export_(Teuchos::rcp(new Tpetra::Export<>(model.maps.overlap_dofs, model.maps.owned_dofs))),
      d_overlap_(model.maps.overlap_dofs),
      f_overlap_(model.maps.overlap_dofs) {
  fault_point("operators");
}

void ModelOperators::internal_force(const Vector& d_owned, Vector& f_owned) const {
  to_overlap(d_owned, d_overlap_);
  f_overlap_.putScalar(0.0);
  // An inverted point on one rank must stop every rank before the export, where the others
  // would otherwise wait for it forever.
  run_collectively(model_.maps.owned_dofs->getComm(), [&] {
    fault_point("internal_force");
    add_internal_force(d_overlap_, f_overlap_);
  });
  to_owned(f_overlap_, f_owned);
}

void ModelOperators::add_internal_force(const Vector& d_overlap, Vector& f_overlap) const {
  solid_.add_internal_force(d_overlap, f_overlap);
  if (mixed_) mixed_->add_internal_force(d_overlap, f_overlap);
}

void ModelOperators::add_tangent(const Vector& d_overlap, FEMatrix& K, BulkTangent bulk) const {
  solid_.add_tangent(d_overlap, K);
  if (mixed_) mixed_->add_tangent(d_overlap, K, bulk);
}

void ModelOperators::add_couplings(CouplingGraph& graph) const {
  solid_.add_point_couplings(graph);
  if (mixed_) mixed_->add_couplings(graph);
}

void ModelOperators::bulk_viscosity(const Vector& v_owned, double linear, double quadratic,
                                    Vector& f_owned) const {
  f_owned.putScalar(0.0);
  if (!mixed_) return;
  to_overlap(v_owned, d_overlap_);
  f_overlap_.putScalar(0.0);
  mixed_->add_bulk_viscosity(d_overlap_, linear, quadratic, f_overlap_);
  to_owned(f_overlap_, f_owned);
}

bool ModelOperators::stiffness_row_bound(const Vector& d_owned, Vector& c_owned) const {
  if (mixed_) return false;
  to_overlap(d_owned, d_overlap_);
  f_overlap_.putScalar(0.0);
  run_collectively(model_.maps.owned_dofs->getComm(),
                   [&] { solid_.add_stiffness_row_bound(d_overlap_, f_overlap_); });
  to_owned(f_overlap_, c_owned);
  return true;
}

double ModelOperators::largest_strain_change(const Vector& delta_owned,
                                             const Vector& d_owned) const {
  to_overlap(delta_owned, f_overlap_);  // (the force's scratch serves the change)
  to_overlap(d_owned, d_overlap_);
  const double mine = solid_.largest_gradient(f_overlap_, d_overlap_);
  double all = 0;
  Teuchos::reduceAll(*model_.maps.owned_dofs->getComm(), Teuchos::REDUCE_MAX, mine,
                     Teuchos::outArg(all));
  return all;
}

long long ModelOperators::eroded_points() const {
  const long long mine = solid_.eroded_points();
  long long all = 0;
  Teuchos::reduceAll(*model_.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM, mine,
                     Teuchos::outArg(all));
  return all;
}

double ModelOperators::strain_energy(const Vector& d_overlap) const {
  return solid_.strain_energy(d_overlap) + (mixed_ ? mixed_->strain_energy(d_overlap) : 0.0);
}

}  // namespace efg
