#include "drivers/BodyForceBalance.hpp"

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Log.hpp"

namespace efg {

namespace {
constexpr int max_balance_iterations = 40;
constexpr double balance_tolerance = 1e-8;

void append(NewtonResult& total, const NewtonResult& step) {
  total.converged = step.converged;
  total.iterations += step.iterations;
  total.linear_iterations += step.linear_iterations;
  total.residual_history.insert(total.residual_history.end(), step.residual_history.begin(),
                                step.residual_history.end());
  auto& r = total.record;
  const auto& s = step.record;
  r.residuals.insert(r.residuals.end(), s.residuals.begin(), s.residuals.end());
  r.linear_iterations.insert(r.linear_iterations.end(), s.linear_iterations.begin(),
                             s.linear_iterations.end());
  r.linear_reductions.insert(r.linear_reductions.end(), s.linear_reductions.begin(),
                             s.linear_reductions.end());
  r.linear_converged.insert(r.linear_converged.end(), s.linear_converged.begin(),
                            s.linear_converged.end());
  r.reason = s.reason;
  r.linear_failure = s.linear_failure;
  total.failure = step.failure;
  total.linear_failure = step.linear_failure;
}
}  // namespace

BodyForceBalance::BodyForceBalance(StaticProblem& problem, std::string where)
    : problem_(problem),
      where_(std::move(where)),
      d_overlap_(problem.model().maps.overlap_dofs),
      r0_(problem.owned_dofs()),
      r1_(problem.owned_dofs()),
      moved_(problem.owned_dofs()) {
  const auto* contact = problem_.contact();
  if (!contact) return;
  const auto& bodies = contact->bodies();
  for (std::size_t b = 0; b < bodies.scene_count(); ++b) {
    if (!bodies.is_free(b) || !contact->acts_on(b)) continue;
    Body body;
    body.index = b;
    body.axis = bodies.static_load_axis(b);
    bodies_.push_back(body);
  }
}

void BodyForceBalance::place(const Body& b, double s) {
  std::array<double, 3> u{};
  for (std::size_t k = 0; k < 3; ++k) u[k] = s * b.axis[k];
  problem_.contact()->set_offset(b.index, u);
}

double BodyForceBalance::residual(const Body& b, const std::vector<BodyResultant>& forces) {
  double R = 0;
  for (std::size_t i = 0; i < 3; ++i) R += b.axis[i] * (b.load[i] + forces[b.index].force[i]);
  return R;
}

void BodyForceBalance::commit() {
  for (auto& b : bodies_) {
    b.last_increment = b.s - b.committed;
    b.committed = b.s;
  }
}

double BodyForceBalance::next_place(Body& b, NewtonSolver& newton, const Vector& d) {
  auto& contact = *problem_.contact();
  const auto& name = contact.bodies().name(b.index);
  b.response = Teuchos::null;
  if (b.residual > 0) {
    b.below = b.has_below ? std::max(b.below, b.s) : b.s;
    b.has_below = true;
  } else {
    b.above = b.has_above ? std::min(b.above, b.s) : b.s;
    b.has_above = true;
  }
  problem_.to_overlap(d, d_overlap_);
  const double stiffness = contact.body_stiffness(d_overlap_, b.index, b.axis.data());
  if (!(stiffness > 0)) {
    // Touches nothing: its load moves it (along +-a) by the nearest gap, and on by the
    // penetration that would carry the load on the particles that touch first, held rigid (a
    // move only into the gap would leave a contact force of round-off size).
    const auto first = contact.first_touch(d_overlap_, b.index, b.axis.data());
    if (b.approaching && !(first.gap < b.gap_before_approach)) {
      std::ostringstream why;
      why << where_ << ": free rigid body '" << name << "' carries a load along (" << b.axis[0]
          << ", " << b.axis[1] << ", " << b.axis[2]
          << ") but touches none of the parts of its contacts, and moving it that way does not "
             "bring it closer (nearest gap "
          << first.gap
          << "); a static stage cannot balance it. Place it on the parts, turn its "
             "force or gravity towards them, or use driver: explicit";
      throw NumericalError(why.str());
    }
    b.approaching = true;
    b.gap_before_approach = first.gap;
    const double move = std::max(first.gap, 0.0) +
                        (first.stiffness > 0 ? std::abs(b.residual) / first.stiffness : 0.0);
    return b.s + (b.residual > 0 ? move : -move);
  }
  b.approaching = false;
  // The Schur complement's slope: the body moved by delta with the particles held (dr/ds),
  // then the particles' response to it, K w = -dr (w = dd/ds delta), and R there.
  // delta: 1e-4 of the body's place plus the penetration that would carry its whole load on
  // the parts held rigid - far below the scale of any change of the active set, far above the
  // round-off of positions (a delta scaled by the shrinking R fell to 1e-12 of s: no slope;
  // 1e-7 left the first slope 20 % off on the flat punch).
  const double delta = 1e-4 * (std::abs(b.s) + std::abs(b.along) / stiffness);
  double slope = -stiffness;  // the parts held rigid: steeper than the true slope
  problem_.residual(d, r0_);
  place(b, b.s + delta);
  problem_.residual(d, r1_);
  r1_.update(-1.0 / delta, r0_, 1.0 / delta);  // dr/ds
  r1_.scale(-1.0);
  auto response = Teuchos::rcp(new Vector(d.getMap()));
  if (newton.solve_tangent(d, r1_, *response) >= 0) {
    moved_.update(1.0, d, delta, *response, 0.0);
    const double coupled = (residual(b, problem_.body_forces(moved_)) - b.residual) / delta;
    if (coupled < 0) {
      slope = coupled;
      b.response = response;
    }
  }
  place(b, b.s);
  double next = b.s - b.residual / slope;
  if (b.has_below && b.has_above &&
      !(next > std::min(b.below, b.above) && next < std::max(b.below, b.above)))
    next = 0.5 * (b.below + b.above);
  return next;
}

NewtonResult BodyForceBalance::solve(NewtonSolver& newton, Vector& d, const Vector& increment,
                                     double ratio, double time, double no_curve) {
  auto& contact = *problem_.contact();
  for (auto& b : bodies_) {
    Body fresh;  // nothing of the last load step's iteration carries over
    fresh.index = b.index;
    fresh.axis = b.axis;
    fresh.committed = b.committed;
    fresh.last_increment = b.last_increment;
    b = fresh;
    b.s = b.committed + ratio * b.last_increment;  // the predictor of the particles' too
    b.load = contact.bodies().static_load(b.index, time, no_curve);
    b.along = 0;
    for (std::size_t i = 0; i < 3; ++i) b.along += b.axis[i] * b.load[i];
    place(b, b.s);
  }
  NewtonResult total;
  for (int k = 0; k < max_balance_iterations; ++k) {
    const auto step = k == 0 ? newton.solve_predicted(d, increment, ratio) : newton.solve(d);
    append(total, step);
    if (!step.converged) return total;
    bool balanced = true;
    const auto forces = problem_.body_forces(d);  // every body's, one collective
    for (auto& b : bodies_) {
      b.residual = residual(b, forces);
      const double tolerance =
          balance_tolerance * std::max(std::abs(b.along), problem_.force_scale());
      std::ostringstream o;
      o << "    free body '" << contact.bodies().name(b.index) << "' at s = " << b.s
        << " along its load " << b.along << ": out of balance by " << b.residual;
      Log::info(o.str());
      if (std::abs(b.residual) > tolerance) balanced = false;
    }
    if (balanced) return total;
    std::vector<double> next(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) next[i] = next_place(bodies_[i], newton, d);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      auto& b = bodies_[i];
      // The particles follow the body along their response (the coupled Newton step).
      if (!b.response.is_null()) d.update(next[i] - b.s, *b.response, 1.0);
      b.s = next[i];
      place(b, b.s);
    }
  }
  total.converged = false;
  total.failure = "the force-controlled rigid bodies did not balance their loads in " +
                  std::to_string(max_balance_iterations) + " placements";
  return total;
}

}  // namespace efg
