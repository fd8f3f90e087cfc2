#include "contact/RigidContact.hpp"
#include "parallel/FaultInjection.hpp"

namespace efg {

RigidContact::RigidContact(const ModelOperators& ops, const Vector& mass_owned,
                           const std::string& stage)
    : bodies_(ops.model().scene, ops.model().mesh.dimension),
      contact_(ops, mass_owned, bodies_, stage),
      surfaces_(SurfaceContact::wanted(ops.model().scene)
                    ? std::make_unique<SurfaceContact>(ops, mass_owned, stage)
                    : nullptr) {}

std::vector<double> RigidContact::wall_forces() const {
  auto forces = contact_.wall_forces();
  if (surfaces_)
    forces.insert(forces.end(), surfaces_->forces().begin(), surfaces_->forces().end());
  return forces;
}

void RigidContact::begin(const std::vector<RigidBodyState>& carried,
                         const std::vector<std::vector<double>>& allowances, double time,
                         const Vector& d_overlap) {
  const bool initial = carried.size() != bodies_.count();
  states_ = initial ? bodies_.initial_states(time) : carried;
  previous_ = states_;
  step_end_ = time;
  contact_.start(d_overlap, states_, initial);
  if (!initial) contact_.carry_allowances(allowances);
  if (surfaces_) surfaces_->start(d_overlap);
}

void RigidContact::move(double time, double dt) {
  previous_ = states_;
  step_start_ = time;
  step_end_ = time + dt;
  bodies_.move(states_, time, dt);
}

void RigidContact::add_forces(const Vector& d_overlap, double dt, Vector& f_overlap) {
  fault_point("contact");
  contact_.add_forces(d_overlap, dt, step_end_, states_, f_overlap);
  if (surfaces_) surfaces_->add_forces(d_overlap, dt, f_overlap);
}

RigidContact::Work RigidContact::finish(double dt) {
  bodies_.finish(states_, step_start_ + dt, dt);
  Work work;
  for (std::size_t b = 0; b < bodies_.count(); ++b)
    if (bodies_.is_free(b))
      for (std::size_t k = 0; k < 3; ++k)
        work.contact += 0.5 * (previous_[b].force[k] + states_[b].force[k]) *
                            (states_[b].displacement[k] - previous_[b].displacement[k]) +
                        0.5 * (previous_[b].moment[k] + states_[b].moment[k]) *
                            (states_[b].rotation[k] - previous_[b].rotation[k]);
  work.gravity = bodies_.applied_work(previous_, states_, step_start_, step_start_ + dt);
  return work;
}

void RigidContact::commit() {
  contact_.commit(states_);
  if (surfaces_) surfaces_->commit();
}

void RigidContact::restore() {
  states_ = previous_;
}

}  // namespace efg
