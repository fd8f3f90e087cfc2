#include "drivers/StaticProblem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>

#include <cmath>
#include <exception>

#include "core/Log.hpp"
#include "parallel/Collective.hpp"
#include "parallel/FaultInjection.hpp"

namespace efg {

StaticProblem::StaticProblem(const Model& model)
    : StaticProblem(std::make_shared<const ModelOperators>(model)) {}

StaticProblem::StaticProblem(std::shared_ptr<const ModelOperators> operators)
    : ops_(std::move(operators)),
      model_(ops_->model()),
      d_overlap_(model_.maps.overlap_dofs),
      r_overlap_(model_.maps.overlap_dofs),
      f_ext_(model_.maps.owned_dofs),
      boundary_owned_(model_.maps.owned_dofs) {
  // The conditions of each implicit stage; stages with the same active conditions share them.
  const auto& scene = model_.scene;
  std::vector<std::string> stages;
  for (const auto& st : scene.stages)
    if (st.driver == "implicit") stages.push_back(st.name);
  if (stages.empty()) stages.push_back("");
  std::map<std::vector<bool>, std::size_t> set_of_key;
  for (const auto& stage : stages) {
    std::vector<bool> key;
    for (const auto& bc : scene.boundary_conditions) key.push_back(bc.stages.includes(stage));
    auto [it, added] = set_of_key.emplace(key, condition_sets_.size());
    if (added)
      condition_sets_.push_back(std::make_unique<EssentialConditions>(
          model_, ops_->solid(), ops_->exact(), EssentialConditions::Selection::all, stage));
    set_of_stage_[stage] = it->second;
  }
  conditions_ = condition_sets_.front().get();
  if (!model_.scene.contacts.empty()) contact_ = std::make_unique<ImplicitContact>(*ops_);
  if (ImplicitSurfaceContact::wanted(model_.scene)) {
    surfaces_ = std::make_unique<ImplicitSurfaceContact>(*ops_);
    d_overlap_.putScalar(0.0);
    surfaces_->refresh_couplings(d_overlap_);  // the reference configuration's reach
  }
  build_graph();
  linear_ = contact_ == nullptr && surfaces_ == nullptr && model_.scene.every_part_linear_elastic();
}

void StaticProblem::build_graph() {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: stiffness graph"));
  CouplingGraph couplings(model_.maps.overlap_nodes->getNodeNumElements());
  ops_->add_couplings(couplings);
  for (const auto& set : condition_sets_) set->add_couplings(couplings);
  if (contact_) contact_->add_couplings(couplings);
  if (surfaces_) surfaces_->add_couplings(couplings);
  graph_ = couplings.build(model_.maps);
}

void StaticProblem::refresh_surface_couplings() {
  if (!surfaces_->refresh_couplings(d_overlap_)) return;
  build_graph();
  graph_changed_ = true;
}

void StaticProblem::commit_history(const Vector& d_owned) {
  const bool rigid_friction = contact_ && contact_->has_friction();
  if (rigid_friction || surfaces_) to_overlap(d_owned, d_overlap_);
  if (rigid_friction) contact_->commit(d_overlap_);
  if (surfaces_) {
    surfaces_->commit(d_overlap_);
    refresh_surface_couplings();
  }
  auto& history = ops_->solid().history();
  if (!history.any()) return;
  Vector r(d_owned.getMap());
  residual(d_owned, r);  // the internal force and the boundary terms, at d
  history.commit();
  conditions_->commit_history();
}

void StaticProblem::begin_stage(const std::vector<RigidBodyState>& bodies, double t0,
                                const std::string& stage, const Vector* d_owned) {
  const auto it = set_of_stage_.find(stage);
  conditions_ = condition_sets_[it == set_of_stage_.end() ? 0 : it->second].get();
  conditions_->load_history();  // an earlier stage may have advanced it
  released_ = Teuchos::null;
  release_scale_ = 0;
  // The state the stage starts from (none: the reference configuration).
  if (d_owned)
    to_overlap(*d_owned, d_overlap_);
  else
    d_overlap_.putScalar(0.0);
  if (contact_) contact_->begin_stage(bodies, t0, stage);
  // (begin_stage left the bodies at their stage-start places)
  if (contact_ && d_owned) contact_->start_friction(d_overlap_);
  if (surfaces_) {
    surfaces_->begin_stage(stage, d_overlap_, t0);
    refresh_surface_couplings();
  }
}

void StaticProblem::begin_release(const Vector& d0_owned) {
  released_ = Teuchos::null;  // the stage's own residual first, without a release term
  auto r0 = Teuchos::rcp(new Vector(model_.maps.owned_dofs));
  unconstrained_residual(d0_owned, *r0);
  released_ = r0;
  release_scale_ = 1;
}

void StaticProblem::set_load_factor(const LoadFactor& factor) {
  conditions_->set_factor(factor);
  ops_->loads().assemble(factor, f_ext_);
  external_norm_ = f_ext_.norm2();
}

void StaticProblem::unconstrained_residual(const Vector& d_owned, Vector& r_owned) {
  to_overlap(d_owned, d_overlap_);
  r_overlap_.putScalar(0.0);
  // A failure among one rank's points (det F <= 0 in a line-search trial) stops every rank here,
  // before the export where the others would wait for it forever (seen on 2 ranks).
  const auto comm = model_.maps.owned_dofs->getComm();
  run_collectively(comm, [&] {
    fault_point("newton");
    ops_->add_internal_force(d_overlap_, r_overlap_);
  });
  ops_->to_owned(r_overlap_, r_owned);
  // The Newton test's force scale: f_int alone, whose rows carry the reactions of the supports
  // and prescribed motions. With the boundary terms and contact forces added the sum vanishes at
  // equilibrium, and a load step that starts converged (the extrapolated predictor on a steady
  // load path) then had only round-off as its scale.
  internal_norm_ = r_owned.norm2();
  r_overlap_.putScalar(0.0);
  run_collectively(comm, [&] {
    {
      Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
      conditions_->add_boundary_terms(d_overlap_, r_overlap_);
    }
    if (contact_) contact_->add_residual(d_overlap_, r_overlap_);
    if (surfaces_) surfaces_->add_residual(d_overlap_, r_overlap_);
  });
  ops_->to_owned(r_overlap_, boundary_owned_);
  r_owned.update(1.0, boundary_owned_, 1.0);
  r_owned.update(-1.0, f_ext_, 1.0);
  if (released_) r_owned.update(-release_scale_, *released_, 1.0);
}

void StaticProblem::residual(const Vector& d_owned, Vector& r_owned) {
  unconstrained_residual(d_owned, r_owned);
  conditions_->replace_rows(d_overlap_, r_owned);
}

void StaticProblem::jacobian(const Vector& d_owned, FEMatrix& K) {
  to_overlap(d_owned, d_overlap_);
  assemble_tangent(K, BulkTangent::full);
}

void StaticProblem::assemble_tangent(FEMatrix& K, BulkTangent bulk) {
  K.beginAssembly();
  K.setAllToScalar(0.0);
  // As in the residual: every rank learns of a failure before the assembly's communication, and
  // the matrix leaves assembly mode either way.
  std::exception_ptr failure;
  try {
    run_collectively(model_.maps.owned_dofs->getComm(), [&] {
      ops_->add_tangent(d_overlap_, K, bulk);
      {
        Teuchos::TimeMonitor timer(
            *Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
        conditions_->add_boundary_terms(d_overlap_, K, bulk);
      }
      if (contact_) contact_->add_tangent(d_overlap_, K);
      if (surfaces_) surfaces_->add_tangent(d_overlap_, K);
    });
  } catch (...) {
    failure = std::current_exception();
  }
  K.endAssembly();
  if (failure) std::rethrow_exception(failure);
  if (surfaces_) {
    // Pairs that came within reach during this load step, beyond the graph's margin: their
    // tangent waits for the graph's refresh at the step's end (Newton converges slower).
    long long mine = surfaces_->take_dropped(), all = 0;
    Teuchos::reduceAll(*model_.maps.owned_dofs->getComm(), Teuchos::REDUCE_SUM, mine,
                       Teuchos::outArg(all));
    if (all > 0)
      Log::info("    contact between parts: " + std::to_string(all) +
                " tangent entries outside the stiffness graph (left out this load step)");
  }
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewCounter("efg: essential conditions"));
  K.beginModify();
  conditions_->replace_rows(K);
  K.endModify();
}

std::vector<BodyResultant> StaticProblem::body_forces(const Vector& d_owned) {
  if (!contact_) return {};
  to_overlap(d_owned, d_overlap_);
  return contact_->body_forces(d_overlap_);
}

std::vector<double> StaticProblem::part_contact_forces(const Vector& d_owned) {
  if (!surfaces_) return {};
  to_overlap(d_owned, d_overlap_);
  return surfaces_->forces(d_overlap_);
}

std::vector<std::array<double, 3>> StaticProblem::reactions(const Vector& d_owned) {
  // f_int - f_ext and the contact forces, without the conditions' own terms: what the supports
  // carry (contact forces on particles a condition reaches are not its reaction).
  Vector r(model_.maps.owned_dofs);
  to_overlap(d_owned, d_overlap_);
  r_overlap_.putScalar(0.0);
  ops_->add_internal_force(d_overlap_, r_overlap_);
  if (contact_) contact_->add_residual(d_overlap_, r_overlap_);
  if (surfaces_) surfaces_->add_residual(d_overlap_, r_overlap_);
  ops_->to_owned(r_overlap_, r);
  r.update(-1.0, f_ext_, 1.0);
  if (released_) r.update(-release_scale_, *released_, 1.0);  // still applied, like a load
  return conditions_->reactions(r);
}

}  // namespace efg

namespace efg {

std::string StaticProblem::bulk_split_misfit() const {
  return efg::bulk_split_misfit(*ops_, *conditions_);
}

BulkSplit StaticProblem::bulk_split() {
  BulkSplit split;
  auto coupling = std::make_shared<BulkCoupling>(*ops_, *conditions_);
  split.relieved = [this, coupling](const Tpetra::CrsMatrix<>& K) {
    if (bulk_scratch_.is_null() || bulk_scratch_graph_ != graph_) {  // contact refreshes it
      bulk_scratch_ = create_matrix();
      bulk_scratch_graph_ = graph_;
    }
    // At the Jacobian's state (d_overlap_), with the mixed parts' bulk stiffness at kappa_0.
    assemble_tangent(*bulk_scratch_, BulkTangent::relieved);
    return coupling->relieved(K, *bulk_scratch_, d_overlap_);
  };
  split.cells = coupling->cells();
  split.pressures = [coupling](const Vector& x, double* q) { coupling->pressures(x, q); };
  split.forces = [coupling](const double* q, Vector& y) { coupling->forces(q, y); };
  split.schur.resize(split.cells);
  ops_->mixed()->bulk_schur_diagonal(split.schur.data());
  split.root_weights.resize(split.cells);
  ops_->mixed()->bulk_weights(split.root_weights.data());
  for (auto& w : split.root_weights) w = std::sqrt(w);
  split.constrained_rows = coupling->constrained_rows();
  split.row_factor = coupling->row_factor();
  return split;
}

}  // namespace efg
