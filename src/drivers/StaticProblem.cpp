#include "drivers/StaticProblem.hpp"

#include <Teuchos_TimeMonitor.hpp>

namespace efg {
namespace {
std::unique_ptr<ExactSolution> exact_of(const Model& model) {
  if (model.scene.exact_solution.empty()) return nullptr;
  return std::make_unique<ExactSolution>(make_exact_solution(model.scene, model.mesh.dimension));
}
}  // namespace

StaticProblem::StaticProblem(const Model& model)
    : model_(model),
      exact_(exact_of(model)),
      solid_(model),
      loads_(model, solid_, exact_.get()),
      conditions_(model, solid_, exact_.get()),
      import_(Teuchos::rcp(new Tpetra::Import<>(model.maps.owned_dofs, model.maps.overlap_dofs))),
      export_(Teuchos::rcp(new Tpetra::Export<>(model.maps.overlap_dofs, model.maps.owned_dofs))),
      d_overlap_(model.maps.overlap_dofs),
      r_overlap_(model.maps.overlap_dofs),
      f_ext_(model.maps.owned_dofs) {
  CouplingGraph couplings(model.maps.overlap_nodes->getNodeNumElements());
  solid_.add_point_couplings(couplings);
  conditions_.add_couplings(couplings);
  graph_ = couplings.build(model.maps);
}

void StaticProblem::set_load_factor(const LoadFactor& factor) {
  conditions_.set_factor(factor);
  loads_.assemble(factor, f_ext_);
}

void StaticProblem::unconstrained_residual(const Vector& d_owned, Vector& r_owned) {
  to_overlap(d_owned, d_overlap_);
  r_overlap_.putScalar(0.0);
  solid_.add_internal_force(d_overlap_, r_overlap_);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
    conditions_.add_boundary_terms(d_overlap_, r_overlap_);
  }
  r_owned.putScalar(0.0);
  r_owned.doExport(r_overlap_, *export_, Tpetra::ADD);
  r_owned.update(-1.0, f_ext_, 1.0);
}

void StaticProblem::residual(const Vector& d_owned, Vector& r_owned) {
  unconstrained_residual(d_owned, r_owned);
  conditions_.replace_rows(d_overlap_, r_owned);
}

void StaticProblem::jacobian(const Vector& d_owned, FEMatrix& K) {
  to_overlap(d_owned, d_overlap_);
  K.beginAssembly();
  K.setAllToScalar(0.0);
  solid_.add_tangent(d_overlap_, K);
  {
    Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
    conditions_.add_boundary_terms(d_overlap_, K);
  }
  K.endAssembly();
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
  K.beginModify();
  conditions_.replace_rows(K);
  K.endModify();
}

std::vector<std::array<double, 3>> StaticProblem::reactions(const Vector& d_owned) {
  to_overlap(d_owned, d_overlap_);
  return conditions_.reactions(d_overlap_);
}

}  // namespace efg
