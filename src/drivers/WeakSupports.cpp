#include "drivers/WeakSupports.hpp"

#include <Teuchos_CommHelpers.hpp>

#include "parallel/Collective.hpp"

namespace efg {

bool WeakSupports::wanted(const Scene& scene, const std::string& stage,
                          bool transformation_traction) {
  for (const auto& bc : scene.boundary_conditions)
    if (bc.type == "displacement" && bc.stages.includes(stage) &&
        (transformation_traction || bc.method != "transformation"))
      return true;
  return false;
}

namespace {
/// True when a displacement condition with the transformation method acts in `stage` and in an
/// implicit stage after it.
bool later_implicit_transformation(const Scene& scene, const std::string& stage) {
  bool after = false;
  for (const auto& later : scene.stages) {
    if (after && later.driver == "implicit")
      for (const auto& bc : scene.boundary_conditions)
        if (bc.type == "displacement" && bc.method == "transformation" &&
            bc.stages.includes(stage) && bc.stages.includes(later.name))
          return true;
    after = after || later.name == stage;
  }
  return false;
}
}  // namespace

WeakSupports::WeakSupports(const ModelOperators& ops, const std::string& stage,
                           bool transformation_traction)
    : ops_(ops),
      last_(ops.model().maps.owned_dofs),
      d_overlap_(ops.model().maps.overlap_dofs),
      r_overlap_(ops.model().maps.overlap_dofs),
      x_overlap_(ops.model().maps.overlap_dofs),
      scratch_(ops.model().maps.owned_dofs) {
  const auto& scene = ops.model().scene;
  bool plastic = false;
  for (const auto& part : scene.parts)
    plastic = plastic || scene.find_material(part.material)->model == "j2_plasticity";
  // With the traction term the transformation points are in conditions_ (and keep their history
  // there); without it only their plastic history is tracked, and only for an implicit stage
  // after this one that carries it on (tracking costs more than the internal force on a Taylor
  // impact, whose only stage is explicit).
  if (plastic && !transformation_traction && later_implicit_transformation(scene, stage))
    tracked_ = std::make_unique<EssentialConditions>(
        ops.model(), ops.solid(), ops.exact(), EssentialConditions::Selection::transformation_only,
        stage);
  if (!wanted(scene, stage, transformation_traction)) return;
  conditions_ = std::make_unique<EssentialConditions>(
      ops.model(), ops.solid(), ops.exact(),
      transformation_traction ? EssentialConditions::Selection::explicit_forces
                              : EssentialConditions::Selection::weak_only,
      stage);
  totals_.assign(conditions_->condition_count(), {0.0, 0.0, 0.0});
}

void WeakSupports::set_time(double time) {
  if (conditions_) conditions_->set_factor(curve_factor(ops_.model().scene, time, 1.0));
}

const Vector& WeakSupports::resistance(const Vector& d_owned) {
  last_.putScalar(0.0);
  if (!conditions_) return last_;
  for (auto& t : totals_) t = {0.0, 0.0, 0.0};
  ops_.to_overlap(d_owned, d_overlap_);
  r_overlap_.putScalar(0.0);
  // det F <= 0 at one rank's boundary point stops every rank before the export.
  run_collectively(ops_.model().maps.owned_dofs->getComm(),
                   [&] { conditions_->add_boundary_terms(d_overlap_, r_overlap_, &totals_); });
  ops_.to_owned(r_overlap_, last_);
  return last_;
}

std::function<void(const Vector&, Vector&)> WeakSupports::stiffness_at(
    const Vector& d_owned) const {
  if (!conditions_) return [](const Vector&, Vector&) {};
  ops_.to_overlap(d_owned, d_overlap_);
  std::shared_ptr<const EssentialConditions::BoundaryTangent> tangent =
      conditions_->boundary_tangent(d_overlap_);
  return [this, tangent](const Vector& x_owned, Vector& y_owned) {
    ops_.to_overlap(x_owned, x_overlap_);
    r_overlap_.putScalar(0.0);
    conditions_->apply_boundary_stiffness(*tangent, x_overlap_, r_overlap_);
    ops_.to_owned(r_overlap_, scratch_);
    y_owned.update(1.0, scratch_, 1.0);
  };
}

std::vector<std::array<double, 3>> WeakSupports::reactions() const {
  const std::size_t n = ops_.model().scene.boundary_conditions.size();
  std::vector<double> local(3 * n, 0.0), global(3 * n, 0.0);
  for (std::size_t c = 0; c < totals_.size(); ++c)
    for (std::size_t k = 0; k < 3; ++k) local[3 * c + k] = -totals_[c][k];
  if (!local.empty())
    Teuchos::reduceAll(*last_.getMap()->getComm(), Teuchos::REDUCE_SUM,
                       static_cast<int>(local.size()), local.data(), global.data());
  std::vector<std::array<double, 3>> out(n);
  for (std::size_t c = 0; c < n; ++c)
    out[c] = {global[3 * c], global[3 * c + 1], global[3 * c + 2]};
  return out;
}

void WeakSupports::commit_history(const Vector& d_owned) {
  if (conditions_) conditions_->commit_history();
  if (tracked_) {
    ops_.to_overlap(d_owned, d_overlap_);
    tracked_->update_history(d_overlap_);
    tracked_->commit_history();
  }
}

}  // namespace efg
