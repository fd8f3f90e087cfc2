// The discrete equilibrium problem of an implicit stage at one load level:
//   r(d) = f_int(d) - lambda f_ext (+ penalty springs, + contact forces), with the constrained
//   rows replaced by the kinematic constraints (transformation method),
// and its Jacobian on a graph built once (rebuilt only when a contact between deformable parts
// comes within reach of new facets: take_graph_change). Knows nothing of the nonlinear solver that drives it.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <string>

#include "contact/ImplicitContact.hpp"
#include "contact/ImplicitSurfaceContact.hpp"
#include "drivers/NonlinearProblem.hpp"
#include "operators/AuxiliaryStiffness.hpp"
#include "operators/BulkSplit.hpp"
#include "operators/EssentialConditions.hpp"
#include "operators/ModelOperators.hpp"

namespace efg {

class StaticProblem : public NonlinearProblem {
 public:
  /// Shares the run's operators; builds the essential conditions and the stiffness graph.
  explicit StaticProblem(std::shared_ptr<const ModelOperators> operators);
  explicit StaticProblem(const Model& model);

  /// Prescribed values and loads at the current load level.
  void set_load_factor(const LoadFactor& factor);
  /// A stage begins: the displacement conditions active in it (stage "": the first implicit
  /// stage's), and the rigid bodies' states at the stage start, time t0 (no-op without
  /// contacts). Ends any release of the previous stage. `d_owned`, the state the stage starts
  /// from, is the reference of the contacts' friction (none: no friction reference).
  void begin_stage(const std::vector<RigidBodyState>& bodies, double t0,
                   const std::string& stage = "", const Vector* d_owned = nullptr);
  /// Springback: r(d0), the residual of the stage's own equations (its conditions, loads and
  /// contacts at the current load factor) at the state it starts from, is subtracted from the
  /// residual scaled by `remaining` (set_release), so d0 is in equilibrium at remaining = 1 and
  /// the unbalance (released supports and tools, the inertia of an explicit state) is gone at 0.
  void begin_release(const Vector& d0_owned);
  void set_release(double remaining) { release_scale_ = remaining; }
  void set_time(double t) {
    if (contact_) contact_->set_time(t);
    if (surfaces_) surfaces_->set_time(t);
  }
  /// Displacements of the rigid bodies at the last set_time (empty without contacts).
  std::vector<std::array<double, 3>> body_displacements() const {
    return contact_ ? contact_->body_displacements() : std::vector<std::array<double, 3>>{};
  }
  /// r = residual(d) on the owned dofs.
  void residual(const Vector& d_owned, Vector& r_owned) override;
  /// K = dr/dd, refilled in place (the graph never changes).
  void jacobian(const Vector& d_owned, FEMatrix& K) override;
  Teuchos::RCP<FEMatrix> create_matrix() const override {
    return Teuchos::rcp(new FEMatrix(graph_));
  }

  /// Accepts the load step converged at d: the material history computed at d (the internal
  /// force is evaluated there once more, whatever point the solver evaluated last) and the
  /// contacts' friction state are committed.
  void commit_history(const Vector& d_owned);

  /// Rotations and orientations of the rigid bodies at the last set_time (empty without
  /// contacts).
  std::vector<std::array<double, 3>> body_rotations() const {
    return contact_ ? contact_->body_rotations() : std::vector<std::array<double, 3>>{};
  }
  std::vector<contact::Orientation> body_orientations() const {
    return contact_ ? contact_->body_orientations() : std::vector<contact::Orientation>{};
  }
  /// The contacts with rigid bodies (null without contacts).
  ImplicitContact* contact() { return contact_.get(); }
  /// Per contact between deformable parts (scene order), the force of its parts on its target
  /// parts at d, 3 components each (collective; empty without such contacts in implicit stages).
  std::vector<double> part_contact_forces(const Vector& d_owned);
  /// True once after the stiffness graph was rebuilt (a contact between deformable parts came
  /// within reach of new facets at an accepted load step): matrices made before are stale.
  bool take_graph_change() {
    const bool changed = graph_changed_;
    graph_changed_ = false;
    return changed;
  }
  /// The contact force on every rigid body at d (collective; empty without contacts).
  std::vector<BodyResultant> body_forces(const Vector& d_owned);

  /// Reactions of every boundary condition at d (after a converged solve).
  std::vector<std::array<double, 3>> reactions(const Vector& d_owned);

  const Teuchos::RCP<const Map>& owned_dofs() const override { return model_.maps.owned_dofs; }
  const SolidOperator& solid() const { return ops_->solid(); }
  const ModelOperators& operators() const { return *ops_; }
  const Model& model() const override { return model_; }
  std::string auxiliary_misfit() const override { return auxiliary_space_misfit(model_.scene); }
  std::string auxiliary_impossible() const override {
    return auxiliary_space_impossible(model_.scene);
  }
  /// The background cells' stiffness, with the current stage's constraint rows from K.
  Teuchos::RCP<const Tpetra::CrsMatrix<>> auxiliary_matrix(
      const Tpetra::CrsMatrix<>& K) const override {
    return auxiliary_stiffness(model_, K, conditions_->constrained_rows());
  }

  std::string bulk_split_misfit() const override;
  BulkSplit bulk_split() override;

  /// The force scale of the last residual evaluation: max(||f_ext||, ||f_int(d)||) (2-norms over
  /// the owned dofs; f_int without the boundary terms, so that it carries the reactions).
  /// Newton's tolerance is relative to it, so that a step that starts converged (a hold stage)
  /// or a load that is reacted by stiff supports is judged in force units.
  double force_scale() const override { return std::max(external_norm_, internal_norm_); }
  /// True when r(d) is affine in d (small-strain linear elastic parts only): one Newton step
  /// with a converged linear solve is then the solution.
  bool linear() const override { return linear_; }
  /// Imports owned values to the overlap map (owned then ghost particles).
  void to_overlap(const Vector& owned, Vector& overlap) const { ops_->to_overlap(owned, overlap); }

 private:
  void unconstrained_residual(const Vector& d_owned, Vector& r_owned);
  /// K at d_overlap_ (the Jacobian's assembly and its collocation rows), the mixed parts' bulk
  /// stiffness at kappa or kappa_0 (operators/BulkTangent.hpp).
  void assemble_tangent(FEMatrix& K, BulkTangent bulk);
  /// The stiffness graph: the operators', the conditions' and the contacts' couplings.
  void build_graph();
  /// The contacts between deformable parts at d_overlap_ reach new facets: rebuild the graph.
  void refresh_surface_couplings();

  std::shared_ptr<const ModelOperators> ops_;
  const Model& model_;
  /// One set of conditions per distinct choice of active conditions among the implicit stages
  /// (usually one); a set keeps its boundary points' history from stage to stage.
  std::vector<std::unique_ptr<EssentialConditions>> condition_sets_;
  std::map<std::string, std::size_t> set_of_stage_;
  EssentialConditions* conditions_ = nullptr;  ///< the current stage's
  std::unique_ptr<ImplicitContact> contact_;   ///< only with contacts in the scene
  /// Only with contacts between deformable parts acting in implicit stages.
  std::unique_ptr<ImplicitSurfaceContact> surfaces_;
  bool graph_changed_ = false;
  Teuchos::RCP<const FEGraph> graph_;
  Vector d_overlap_, r_overlap_, f_ext_;
  Teuchos::RCP<FEMatrix> bulk_scratch_;  ///< the bulk split's relieved matrix A (first use)
  Teuchos::RCP<const FEGraph> bulk_scratch_graph_;  ///< the graph it was built on
  Vector boundary_owned_;          ///< the boundary terms' and contacts' share of the residual
  Teuchos::RCP<Vector> released_;  ///< springback: r(d0) of the stage (null: no release)
  double release_scale_ = 0;
  double external_norm_ = 0, internal_norm_ = 0;
  bool linear_ = false;
};

}  // namespace efg
