#include "drivers/ShellStaticProblem.hpp"

#include <algorithm>

namespace efg {

ShellStaticProblem::ShellStaticProblem(const Model& model, const FlatShellOperator& op,
                                       const std::vector<ShellSupport>& supports)
    : model_(model),
      op_(op),
      constraints_(model, op, supports),
      f_ext_(op.maps().owned_dofs),
      d_overlap_(op.maps().overlap_dofs),
      values_(constraints_.collocation_values(supports)),
      accepted_(values_.size(), 0.0) {
  for (const auto& [support, component] : constraints_.row_supports())
    rotation_row_.push_back(component >= shell_rx);
  // The collocation rows' scales come from the tangent's rows at the start (kept afterwards).
  auto K = create_matrix();
  op_.fill_tangent(Vector(op.maps().owned_dofs), constraints_, *K);
}

void ShellStaticProblem::set_level(const FlatShellOperator::Pressure& pressure,
                                   const std::vector<ShellSupport>& supports,
                                   const std::function<void(Vector&)>& more_loads,
                                   const FlatShellOperator::Pressure& follower) {
  follower_ = follower;
  f_ext_.putScalar(0.0);
  op_.add_pressure(pressure, f_ext_);
  if (more_loads) more_loads(f_ext_);
  constraints_.zero_constrained(f_ext_);
  external_norm_ = f_ext_.norm2();
  values_ = constraints_.collocation_values(supports);
  constraints_.set_edge_values(supports);
  if (op_.finite_rotations())  // the step's rotation (shells/FiniteRotation.hpp)
    for (std::size_t k = 0; k < values_.size(); ++k)
      if (rotation_row_[k]) values_[k] -= accepted_[k];
}

void ShellStaticProblem::residual(const Vector& d_owned, Vector& r_owned) {
  op_.internal_force(d_owned, r_owned, &constraints_);  // with the edge terms
  constraints_.zero_constrained(r_owned);
  internal_norm_ = r_owned.norm2();
  r_owned.update(-1.0, f_ext_, 1.0);
  if (follower_) {
    Vector f(op_.maps().owned_dofs);
    f.update(1.0, f_ext_, 0.0);
    op_.add_follower_pressure(follower_, d_owned, f);
    constraints_.zero_constrained(f);
    external_norm_ = f.norm2();
    f.update(-1.0, f_ext_, 1.0);  // the follower part alone
    r_owned.update(-1.0, f, 1.0);
  }
  if (released_) r_owned.update(-remaining_, *released_, 1.0);
  op_.to_overlap(d_owned, d_overlap_);
  constraints_.constrained_residual(d_overlap_, values_, r_owned);
}

void ShellStaticProblem::begin_release(const Vector& d0_owned) {
  released_.reset();  // the stage's own residual first, without a release term
  auto r0 = std::make_unique<Vector>(op_.maps().owned_dofs);
  residual(d0_owned, *r0);
  constraints_.zero_constrained(*r0);
  released_ = std::move(r0);
  remaining_ = 1;
}

void ShellStaticProblem::jacobian(const Vector& d_owned, FEMatrix& K) {
  op_.fill_tangent(d_owned, constraints_, K, follower_ ? &follower_ : nullptr);
}

void ShellStaticProblem::commit(Vector& d_owned) {
  Vector r(op_.maps().owned_dofs);
  residual(d_owned, r);  // every point's and edge point's trial state at d
  op_.commit_state();
  constraints_.commit();
  if (!op_.finite_rotations()) return;
  op_.accept_rotations(d_owned);
  for (std::size_t k = 0; k < values_.size(); ++k)
    if (rotation_row_[k]) accepted_[k] += values_[k];
}

}  // namespace efg
