#include "contact/PenaltyContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contact/CandidateCounts.hpp"
#include "contact/CoulombFriction.hpp"
#include "contact/PenaltyForce.hpp"
#include "core/Errors.hpp"
#include "scene/ContactInput.hpp"

namespace efg {

double PenaltyContact::largest_share(const Scene& scene) {
  double share = 0;
  for (const auto& c : scene.contacts) share = std::max(share, contact_stability_share(c));
  return share;
}

PenaltyContact::PenaltyContact(const ModelOperators& ops, const Vector& mass_owned,
                               const RigidBodies& bodies, const std::string& stage)
    : dim_(ops.model().mesh.dimension),
      bodies_(bodies),
      comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  // Candidate: owned particle j of part p, with its mass and shape-function row.
  auto candidate = [&](std::size_t p, std::size_t j) {
    Candidate c;
    c.row = particle_row(ops, p, j);
    c.mass = particle_mass(model, mass, p, j);
    return c;
  };
  for (const auto& spec : model.scene.contacts) {
    // a tool this stage does without, or a contact between deformable parts (SurfaceContact)
    if (!spec.stages.includes(stage) || spec.rigid_body.empty()) continue;
    Pair pair;
    for (std::size_t b = 0; b < bodies.scene_count(); ++b)
      if (bodies.name(b) == spec.rigid_body) pair.body = b;
    pair.penalty = spec.penalty;
    pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
    pair.damping = spec.damping;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      const auto on_surface = surface_nodes(model, p);
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j)
        if (on_surface[static_cast<std::size_t>(part.cloud.mesh_node[j])])
          pair.candidates.push_back(candidate(p, j));
    }
    pairs_.push_back(std::move(pair));
  }
  // Rigid walls: frictionless, undamped, on every particle of their node set (all particles
  // without one), as the planar rigid walls always were.
  for (std::size_t w = 0; w < model.scene.rigid_walls.size(); ++w) {
    const auto& spec = model.scene.rigid_walls[w];
    Pair pair;
    pair.body = bodies.wall(w);
    pair.penalty = spec.penalty;
    std::vector<char> in_set(model.mesh.node_count(), spec.node_set.empty() ? 1 : 0);
    if (!spec.node_set.empty())
      for (auto n : model.mesh.find_node_set(spec.node_set)->nodes)
        in_set[static_cast<std::size_t>(n)] = 1;
    for (std::size_t p = 0; p < model.parts.size(); ++p)
      for (std::size_t j = 0; j < model.parts[p].cloud.owned_count; ++j)
        if (in_set[static_cast<std::size_t>(model.parts[p].cloud.mesh_node[j])])
          pair.candidates.push_back(candidate(p, j));
    pairs_.push_back(std::move(pair));
  }
}

void PenaltyContact::start(const Vector& d_overlap, const std::vector<RigidBodyState>& bodies) {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    pair.body_rotation_old = bodies[pair.body].rotation;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new = c.row.position(d, udim);
      c.ft_old = c.ft_new = {0.0, 0.0, 0.0};
    }
  }
}

void PenaltyContact::add_forces(const Vector& d_overlap, double dt,
                                std::vector<RigidBodyState>& bodies, Vector& f_overlap) {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  // Per body: the force on it (3), penalty x the mass of its touching particles, the total
  // normal force (the rigid walls' history column) and the moment about its reference point (3).
  constexpr std::size_t kPer = 8;
  const std::size_t nb = bodies_.count();
  std::vector<double> local(kPer * nb, 0.0), total(kPer * nb, 0.0);
  for (auto& pair : pairs_) {
    const auto& shape = bodies_.shape(pair.body);
    const auto& u_body = bodies[pair.body].displacement;
    const double k_per_mass = pair.penalty / (dt * dt);
    for (auto& c : pair.candidates) {
      c.x_new = c.row.position(d, udim);
      const auto near =
          contact::proximity_of_body(shape, c.x_new.data(), u_body.data(),
                                     bodies[pair.body].rotation[2], bodies[pair.body].orientation);
      c.active = near.gap < 0;
      if (!c.active) {
        c.ft_new = {0.0, 0.0, 0.0};
        continue;
      }
      const double k = k_per_mass * c.mass;
      // The particle's motion relative to the body's surface point over the step (translation,
      // and the turn of a rotating body): its normal part is the approach (damping), its
      // tangential part the slip (friction).
      const auto& body = bodies[pair.body];
      double dtheta[3], s[3], F[3] = {0, 0, 0};
      for (std::size_t i = 0; i < 3; ++i) dtheta[i] = body.rotation[i] - pair.body_rotation_old[i];
      contact::slip_against_body(shape, c.x_new.data(), c.x_old.data(), u_body.data(),
                                 pair.body_u_old.data(), dtheta, dim_, s);
      const double fn = contact::penalty_force(near, s, k, c.mass, pair.damping, pair.friction,
                                               c.ft_old.data(), dt, dim_, c.ft_new.data(), F);
      c.row.spread(F, udim, f);
      const double on_body[3] = {-F[0], -F[1], -F[2]};
      for (std::size_t i = 0; i < udim; ++i) local[kPer * pair.body + i] += on_body[i];
      local[kPer * pair.body + 3] += pair.penalty * c.mass;
      local[kPer * pair.body + 4] += fn;
      contact::add_moment(shape, u_body.data(), c.x_new.data(), on_body,
                          &local[kPer * pair.body + 5]);
    }
  }
  if (nb > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
  wall_forces_.assign(nb - bodies_.scene_count(), 0.0);
  for (std::size_t b = 0; b < nb; ++b) {
    for (std::size_t i = 0; i < 3; ++i) {
      bodies[b].force[i] = total[kPer * b + i];
      bodies[b].moment[i] = total[kPer * b + 5 + i];
    }
    if (b >= bodies_.scene_count()) wall_forces_[b - bodies_.scene_count()] = total[kPer * b + 4];
    // A free body's own contact frequency: omega^2 dt^2 = sum k_J dt^2 / M = penalty sum m_J / M;
    // central differences need it below 4, kept below 1 with the particles' share.
    bodies_.check_contact_mass(b, total[kPer * b + 3]);
  }
}

void PenaltyContact::commit(const std::vector<RigidBodyState>& bodies) {
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    pair.body_rotation_old = bodies[pair.body].rotation;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new;
      c.ft_old = c.ft_new;
    }
  }
}

long long PenaltyContact::active_count() const {
  return contact::active_over_ranks(*comm_, pairs_);
}

long long PenaltyContact::candidate_count() const {
  return contact::candidates_over_ranks(*comm_, pairs_);
}

}  // namespace efg
