// The discrete equilibrium of an implicit shell stage at one load level (the shells' side of
// drivers/NonlinearProblem, driven by the same NOX Newton as the solids):
//   r(d) = f_int(d) + f_edge(d) - f_ext - f_follower(d)
// with f_int the point-by-point internal force of FlatShellOperator (elastic sections or J2
// through the thickness), f_edge the transformation conditions' edge traction terms
// (ShellConstraints; J2 edge points carry their own layers), f_ext the dead loads (shell
// pressure, edge loads), f_follower a follower pressure (finite rotations), f_edge also the
// nitsche and penalty supports' boundary terms (small rotations), and the
// rows of constrained dofs replaced by their scaled collocation equations s (C d - g). The
// Jacobian is FlatShellOperator::fill_tangent, the exact derivative of r (tested against central
// differences).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "drivers/NonlinearProblem.hpp"
#include "shells/FlatShellOperator.hpp"
#include "shells/ShellConstraints.hpp"

namespace efg {

class ShellStaticProblem : public NonlinearProblem {
 public:
  /// `supports` fixes which dofs are held (their values are set per load level).
  ShellStaticProblem(const Model& model, const FlatShellOperator& op,
                     const std::vector<ShellSupport>& supports);

  /// The loads and prescribed values of a load level: the pressure, further loads added to the
  /// external force by `more_loads` (edge line loads), the supports' values, and a follower
  /// pressure (empty: none), whose force depends on d (residual and tangent). With finite
  /// rotations a held rotation's row prescribes its change since the last accepted step (the
  /// rotation dofs are that change, the frames carry the rest): the level's value less the
  /// accepted one (start_rotations, then every commit).
  void set_level(const FlatShellOperator::Pressure& pressure,
                 const std::vector<ShellSupport>& supports,
                 const std::function<void(Vector&)>& more_loads = {},
                 const FlatShellOperator::Pressure& follower = {});

  /// The supports' rotations the frames carry at the stage's start (finite rotations).
  void start_rotations(const std::vector<ShellSupport>& supports) {
    accepted_ = constraints_.collocation_values(supports);
  }

  void residual(const Vector& d_owned, Vector& r_owned) override;
  void jacobian(const Vector& d_owned, FEMatrix& K) override;
  Teuchos::RCP<FEMatrix> create_matrix() const override { return op_.create_matrix(constraints_); }
  const Teuchos::RCP<const Tpetra::Map<>>& owned_dofs() const override {
    return op_.maps().owned_dofs;
  }
  /// max(||f_ext||, ||f_int + f_edge|| on the free rows) of the last residual.
  double force_scale() const override { return std::max(external_norm_, internal_norm_); }
  bool linear() const override { return !op_.plastic() && !op_.finite_rotations(); }
  const Model& model() const override { return model_; }
  bool displacement_dofs() const override { return false; }
  bool residual_norm_is_a_merit() const override { return !op_.finite_rotations(); }

  /// Accepts the load step converged at d: the J2 layers of the points and of the edge points
  /// evaluated at d become the committed states; with finite rotations the particles' frames
  /// take the step's rotations, whose dofs in d become 0 (FlatShellOperator::accept_rotations).
  void commit(Vector& d_owned);

  /// Springback (as the solids' StaticProblem::begin_release): r(d0) of the stage's own
  /// equations at the current level, free rows, is subtracted from the residual scaled by
  /// `remaining` (set_release), so d0 is in equilibrium at remaining = 1 and the forces out of
  /// balance (released supports and loads, an explicit state's inertia) are gone at 0.
  void begin_release(const Vector& d0_owned);
  void set_release(double remaining) { remaining_ = remaining; }

 private:
  const Model& model_;
  const FlatShellOperator& op_;
  ShellConstraints constraints_;
  Vector f_ext_, d_overlap_;
  std::vector<double> values_;  ///< the supports' values, collocation rows' order
  /// finite rotations: the held rotations' values at the last accepted step (rows' order; the
  /// translation rows' entries unused) and which rows hold a rotation
  std::vector<double> accepted_;
  std::vector<char> rotation_row_;
  double external_norm_ = 0, internal_norm_ = 0;
  std::unique_ptr<Vector> released_;      ///< springback: r(d0) on the free rows (null: none)
  FlatShellOperator::Pressure follower_;  ///< the level's follower pressure (empty: none)
  double remaining_ = 0;
};

}  // namespace efg
