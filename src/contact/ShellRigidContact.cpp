#include "contact/ShellRigidContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>

#include "contact/PenaltyForce.hpp"

namespace efg {
namespace {
constexpr std::size_t nd = shell_dofs_per_node;
}  // namespace

bool ShellRigidContact::wanted(const Scene& scene, const std::string& stage) {
  return std::any_of(scene.contacts.begin(), scene.contacts.end(), [&](const ContactSpec& c) {
    return !c.rigid_body.empty() && c.stages.includes(stage);
  });
}

ShellRigidContact::ShellRigidContact(const Model& model, const FlatShellOperator& op,
                                     const Vector& mass_owned, const std::string& stage)
    : model_(model), op_(op), bodies_(model.scene, 3) {
  const auto& overlap = *op.maps().overlap_nodes;
  const auto lid = [&](LocalIndex node) {
    return overlap.getLocalElement(global_node_id(model, node));
  };
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& spec : model.scene.contacts) {
    if (spec.rigid_body.empty() || !spec.stages.includes(stage)) continue;
    Pair pair;
    for (std::size_t b = 0; b < bodies_.scene_count(); ++b)
      if (bodies_.name(b) == spec.rigid_body) pair.body = b;
    pair.penalty = spec.penalty;
    pair.damping = spec.damping;
    pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
    share_ = std::max(share_, spec.penalty + 2 * spec.damping);
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      const auto& rows = part.particle_values();
      for (std::size_t r = 0; r < part.cloud.owned_count; ++r) {
        Candidate c;
        const auto node = part.cloud.mesh_node[r];
        const double* X = model.mesh.coordinates.data() + 2 * static_cast<std::size_t>(node);
        c.X = {X[0], X[1], 0.0};
        for (auto k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
          c.nodes.push_back(lid(part.cloud.mesh_node[static_cast<std::size_t>(rows.particles[k])]));
          c.phi.push_back(rows.values[k]);
        }
        const auto own = static_cast<std::size_t>(lid(node));
        c.mass = mass(own * nd, 0);
        c.half_thickness = 0.5 * op.node_thickness(p, static_cast<int>(own));
        pair.candidates.push_back(std::move(c));
      }
    }
    pairs_.push_back(std::move(pair));
  }
}

void ShellRigidContact::start(double time, double dt) {
  dt_ = dt;
  impulse_.assign(3 * bodies_.scene_count(), 0.0);
  states_ = bodies_.initial_states(time);
  for (std::size_t b = 0; b < states_.size(); ++b)
    states_[b].displacement = bodies_.prescribed_travel(b, 0.0, time);
  for (auto& pair : pairs_) {
    pair.body_u_old = states_[pair.body].displacement;
    pair.body_rotation_old = states_[pair.body].rotation;
    for (auto& c : pair.candidates) {
      c.started = false;
      c.ft = {0.0, 0.0, 0.0};
    }
  }
}

void ShellRigidContact::move(double time, double dt) {
  bodies_.move(states_, time, dt);
}

void ShellRigidContact::finish(double time_end, double dt) {
  bodies_.finish(states_, time_end, dt);
}

std::vector<double> ShellRigidContact::body_velocities() const {
  std::vector<double> out;
  for (std::size_t b = 0; b < bodies_.scene_count(); ++b)
    for (std::size_t k = 0; k < 3; ++k) out.push_back(states_[b].velocity[k]);
  return out;
}

void ShellRigidContact::forces(const Vector& d_owned, double step, Vector& f_owned) {
  Vector d_overlap(op_.maps().overlap_dofs), f_overlap(op_.maps().overlap_dofs);
  op_.to_overlap(d_owned, d_overlap);
  // per body: the force on it (3) and penalty x the mass of the particles it touches
  const std::size_t count = 4 * states_.size();
  std::vector<double> local(count, 0.0);
  std::vector<double> total(count, 0.0);
  {
    const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (auto& pair : pairs_) {
      const auto& shape = bodies_.shape(pair.body);
      const auto& state = states_[pair.body];
      const double k_per_mass = pair.penalty / (dt_ * dt_);
      for (auto& c : pair.candidates) {
        std::array<double, 3> x = c.X;
        for (std::size_t a = 0; a < c.nodes.size(); ++a)
          for (std::size_t k = 0; k < 3; ++k)
            x[k] += c.phi[a] * d(static_cast<std::size_t>(c.nodes[a]) * nd + k, 0);
        const auto near = contact::proximity_of_body(shape, x.data(), state.displacement.data(),
                                                     state.rotation[2], state.orientation);
        // the sheet's face on the body's side is half the thickness nearer
        auto face = near;
        face.gap -= c.half_thickness;
        double dtheta[3], s_rel[3] = {0, 0, 0};
        for (std::size_t k = 0; k < 3; ++k)
          dtheta[k] = state.rotation[k] - pair.body_rotation_old[k];
        if (c.started)
          contact::slip_against_body(shape, x.data(), c.x_old.data(), state.displacement.data(),
                                     pair.body_u_old.data(), dtheta, 3, s_rel);
        c.x_old = x;
        c.started = true;
        if (face.gap >= 0) {
          c.ft = {0.0, 0.0, 0.0};
          continue;
        }
        double F[3], ft[3] = {0, 0, 0};
        contact::penalty_force(face, s_rel, k_per_mass * c.mass, c.mass, pair.damping,
                               pair.friction, c.ft.data(), step, 3, ft, F);
        c.ft = {ft[0], ft[1], ft[2]};  // every explicit step is accepted
        for (std::size_t k = 0; k < 3; ++k) {
          for (std::size_t a = 0; a < c.nodes.size(); ++a)
            f(static_cast<std::size_t>(c.nodes[a]) * nd + k, 0) += c.phi[a] * F[k];
          local[4 * pair.body + k] -= F[k];
        }
        local[4 * pair.body + 3] += pair.penalty * c.mass;
      }
      pair.body_u_old = state.displacement;
      pair.body_rotation_old = state.rotation;
    }
  }
  f_owned.putScalar(0.0);
  op_.add_overlap(f_overlap, f_owned);
  Teuchos::reduceAll(*op_.maps().owned_dofs->getComm(), Teuchos::REDUCE_SUM,
                     static_cast<int>(local.size()), local.data(), total.data());
  for (std::size_t b = 0; b < states_.size(); ++b) {
    for (std::size_t k = 0; k < 3; ++k) states_[b].force[k] = total[4 * b + k];
    bodies_.check_contact_mass(b, total[4 * b + 3], " with the shell");
  }
}

void ShellRigidContact::accumulate(double step) {
  for (std::size_t b = 0; b < bodies_.scene_count(); ++b)
    for (std::size_t k = 0; k < 3; ++k) impulse_[3 * b + k] += step * states_[b].force[k];
}

std::vector<double> ShellRigidContact::mean_body_forces(double elapsed) {
  std::vector<double> out(impulse_.size());
  for (std::size_t b = 0; b < bodies_.scene_count(); ++b)
    for (std::size_t k = 0; k < 3; ++k)
      out[3 * b + k] = elapsed > 0 ? impulse_[3 * b + k] / elapsed : states_[b].force[k];
  std::fill(impulse_.begin(), impulse_.end(), 0.0);
  return out;
}

}  // namespace efg
