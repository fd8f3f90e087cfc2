#include "contact/PenaltyContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "contact/BoundaryShares.hpp"
#include "contact/CandidateCounts.hpp"
#include "contact/ContactStiffness.hpp"
#include "contact/CoulombFriction.hpp"
#include "contact/PenaltyForce.hpp"
#include "contact/PenetrationChecks.hpp"
#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "scene/ContactInput.hpp"

namespace efg {
namespace {
// The bulk modulus of part p's material (contact/ContactStiffness.hpp); with a graded Young's
// modulus its largest value over the part (scene.materials[].constants, set by build_model).
double part_bulk_modulus(const Model& model, std::size_t p) {
  const auto& part = *model.parts[p].part;
  const auto& k = model.scene.find_material(part.material)->constants;
  return contact::bulk_modulus(k.at("youngs_modulus"), k.at("poissons_ratio"),
                               model.mesh.dimension == 2 && part.plane_stress);
}
}  // namespace

double PenaltyContact::largest_share(const Scene& scene) {
  double share = 0;
  for (const auto& c : scene.contacts) share = std::max(share, contact_stability_share(c));
  return share;
}

PenaltyContact::PenaltyContact(const ModelOperators& ops, const Vector& mass_owned,
                               const RigidBodies& bodies, const std::string& stage)
    : dim_(ops.model().mesh.dimension),
      bodies_(bodies),
      comm_(ops.model().maps.owned_dofs->getComm()),
      model_(ops.model()) {
  const auto& model = ops.model();
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  // Each part's boundary shares (area A_J, spacing h_J) and its smallest spacing over the ranks.
  std::vector<BoundaryShares> shares;
  std::vector<std::vector<SideShares>> sides;
  std::vector<double> smallest(model.parts.size(), std::numeric_limits<double>::max());
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    shares.push_back(part_boundary_shares(model, p));
    sides.push_back(part_side_shares(model, p));
    for (std::size_t n = 0; n < shares[p].size.size(); ++n)
      if (shares[p].area[n] > 0) smallest[p] = std::min(smallest[p], shares[p].size[n]);
  }
  part_spacing_.assign(model.parts.size(), 0.0);
  if (!smallest.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, static_cast<int>(smallest.size()),
                       smallest.data(), part_spacing_.data());
  // Candidate: owned particle j of part p, with its mass, shape-function row, spacing and the
  // material rule's stiffness at `scale` (0: none).
  auto candidate = [&](std::size_t p, std::size_t j, double scale) {
    Candidate c;
    c.row = particle_row(ops, p, j);
    c.mass = particle_mass(model, mass, p, j);
    c.part = p;
    const auto node = static_cast<std::size_t>(model.parts[p].cloud.mesh_node[j]);
    c.particle = static_cast<long long>(model.mesh.global_node(node));
    c.spacing = shares[p].size[node] > 0 ? shares[p].size[node] : part_spacing_[p];
    if (scale > 0 && shares[p].size[node] > 0) {
      c.k_per_area = contact::material_stiffness(scale, part_bulk_modulus(model, p), 1.0,
                                                 shares[p].size[node]);
      c.sides = sides[p][node];
    }
    return c;
  };
  double w2 = 0, damping = 0;
  for (std::size_t ci = 0; ci < model.scene.contacts.size(); ++ci) {
    const auto& spec = model.scene.contacts[ci];
    // a tool this stage does without, or a contact between deformable parts (SurfaceContact)
    if (!spec.stages.includes(stage) || spec.rigid_body.empty()) continue;
    Pair pair;
    for (std::size_t b = 0; b < bodies.scene_count(); ++b)
      if (bodies.name(b) == spec.rigid_body) pair.body = b;
    pair.contact = static_cast<long>(ci);
    pair.penalty = spec.penalty;
    pair.warning = spec.penetration_warning;
    pair.initial = spec.initial_penetration;
    pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
    pair.damping = spec.damping;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      const auto on_surface = surface_nodes(model, p);
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j)
        if (on_surface[static_cast<std::size_t>(part.cloud.mesh_node[j])]) {
          pair.candidates.push_back(candidate(p, j, spec.penalty_scale));
          const auto& c = pair.candidates.back();
          if (c.k_per_area > 0) {
            w2 = std::max(w2, c.k_per_area * contact::largest_facing_area(c.sides) / c.mass);
            damping = std::max(damping, spec.damping);
          }
        }
    }
    pairs_.push_back(std::move(pair));
  }
  // Rigid walls: frictionless, undamped, on every particle of their node set (all particles
  // without one), with the mass rule alone, as the planar rigid walls always were.
  for (std::size_t w = 0; w < model.scene.rigid_walls.size(); ++w) {
    const auto& spec = model.scene.rigid_walls[w];
    Pair pair;
    pair.body = bodies.wall(w);
    pair.wall = static_cast<long>(w);
    pair.penalty = spec.penalty;
    std::vector<char> in_set(model.mesh.node_count(), spec.node_set.empty() ? 1 : 0);
    if (!spec.node_set.empty())
      for (auto n : model.mesh.find_node_set(spec.node_set)->nodes)
        in_set[static_cast<std::size_t>(n)] = 1;
    for (std::size_t p = 0; p < model.parts.size(); ++p)
      for (std::size_t j = 0; j < model.parts[p].cloud.owned_count; ++j)
        if (in_set[static_cast<std::size_t>(model.parts[p].cloud.mesh_node[j])])
          pair.candidates.push_back(candidate(p, j, 0.0));
    pairs_.push_back(std::move(pair));
  }
  double local[2] = {w2, damping}, all[2] = {0, 0};
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 2, local, all);
  material_w2_ = all[0];
  material_damping_ = all[1];
}

void PenaltyContact::start(const Vector& d_overlap, const std::vector<RigidBodyState>& bodies,
                           bool initial) {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    pair.body_rotation_old = bodies[pair.body].rotation;
    pair.peak = pair.stage_peak = 0;
    pair.warned = false;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new = c.row.position(d, udim);
      c.ft_old = c.ft_new = {0.0, 0.0, 0.0};
      c.allowance = c.allowance_new = 0;
    }
  }
  if (initial) initial_overlaps(bodies);  // a later stage: penetrations are its own work
}

void PenaltyContact::slip(const Pair& pair, const Candidate& c,
                          const std::vector<RigidBodyState>& bodies, double* s) const {
  const auto& body = bodies[pair.body];
  double dtheta[3];
  for (std::size_t i = 0; i < 3; ++i) dtheta[i] = body.rotation[i] - pair.body_rotation_old[i];
  contact::slip_against_body(bodies_.shape(pair.body), c.x_new.data(), c.x_old.data(),
                             body.displacement.data(), pair.body_u_old.data(), dtheta, dim_, s);
}

void PenaltyContact::add_forces(const Vector& d_overlap, double dt, double time,
                                std::vector<RigidBodyState>& bodies, Vector& f_overlap) {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  // Per body: the force on it (3), k dt^2 summed over its touching particles (the mass rule's
  // penalty x mass), the total normal force (the rigid walls' history column) and the moment
  // about its reference point (3).
  constexpr std::size_t kPer = 8;
  const std::size_t nb = bodies_.count(), np = part_spacing_.size();
  std::vector<double> local(kPer * nb, 0.0), total(kPer * nb, 0.0);
  // Per pair the deepest particle over its spacing; per pair and part the largest travel
  // against the body near it over the part's spacing (contact/PenetrationChecks.hpp).
  std::vector<double> deepest(pairs_.size(), 0.0), travel(pairs_.size() * np, 0.0);
  for (std::size_t pi = 0; pi < pairs_.size(); ++pi) {
    auto& pair = pairs_[pi];
    const auto& shape = bodies_.shape(pair.body);
    const auto& u_body = bodies[pair.body].displacement;
    const double k_per_mass = pair.penalty / (dt * dt);
    for (auto& c : pair.candidates) {
      c.x_new = c.row.position(d, udim);
      auto near =
          contact::proximity_of_body(shape, c.x_new.data(), u_body.data(),
                                     bodies[pair.body].rotation[2], bodies[pair.body].orientation);
      // The particle's motion relative to the body's surface point over the step (translation,
      // and the turn of a rotating body): its normal part is the approach (damping), its
      // tangential part the slip (friction), its length the travel that tunnelling is about.
      double s[3], F[3] = {0, 0, 0};
      slip(pair, c, bodies, s);
      const double moved = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      const double h = part_spacing_[c.part];
      // ignored initial depth: the allowance shrinks as the particle comes out, never grows
      c.allowance_new = std::min(c.allowance, std::max(0.0, -near.gap));
      near.gap += c.allowance_new;
      // (rigid walls keep their behaviour: a bar thrown at a wall at its wave speed stops where
      // its particles pass through each other, cli.small_strain_breakdown)
      if (pair.contact >= 0 && near.gap < moved + h) {
        auto& t = travel[pi * np + c.part];
        t = std::max(t, moved / h);
      }
      c.active = near.gap < 0;
      if (!c.active) {
        c.ft_new = {0.0, 0.0, 0.0};
        continue;
      }
      deepest[pi] = std::max(deepest[pi], -near.gap / c.spacing);
      const double k =
          std::max(c.k_per_area * contact::facing_area(c.sides, near.normal), k_per_mass * c.mass);
      const double fn = contact::penalty_force(near, s, k, c.mass, pair.damping, pair.friction,
                                               c.ft_old.data(), dt, dim_, c.ft_new.data(), F);
      c.row.spread(F, udim, f);
      const double on_body[3] = {-F[0], -F[1], -F[2]};
      for (std::size_t i = 0; i < udim; ++i) local[kPer * pair.body + i] += on_body[i];
      local[kPer * pair.body + 3] += k * dt * dt;
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
    // A free body's own contact frequency: omega^2 dt^2 = sum k_J dt^2 / M; central differences
    // need it below 4, kept below 1 with the particles' share.
    bodies_.check_contact_mass(b, total[kPer * b + 3]);
  }
  watch(deepest, travel, time);
}

void PenaltyContact::watch(std::vector<double>& deepest, std::vector<double>& travel, double time) {
  std::vector<double> mine(deepest), all;
  mine.insert(mine.end(), travel.begin(), travel.end());
  all.assign(mine.size(), 0.0);
  if (!mine.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, static_cast<int>(mine.size()), mine.data(),
                       all.data());
  const std::size_t np = part_spacing_.size();
  for (std::size_t pi = 0; pi < pairs_.size(); ++pi) {
    auto& pair = pairs_[pi];
    const double depth = all[pi];
    pair.peak = std::max(pair.peak, depth);
    pair.stage_peak = std::max(pair.stage_peak, depth);
    if (pair.contact >= 0 && !pair.warned && depth > pair.warning) {
      pair.warned = true;
      const auto& spec = model_.scene.contacts[static_cast<std::size_t>(pair.contact)];
      Log::warning(
          contact::penetration_warning(spec.name, spec.rigid_body, depth, pair.warning, time));
    }
    for (std::size_t p = 0; p < np; ++p) {
      const double ratio = all[pairs_.size() + pi * np + p];
      if (ratio > contact::kTunnellingFraction)
        throw NumericalError(
            contact::tunnelling_message(bodies_.name(pair.body), model_.parts[p].part->name,
                                        ratio * part_spacing_[p], part_spacing_[p]));
    }
  }
}

void PenaltyContact::commit(const std::vector<RigidBodyState>& bodies) {
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    pair.body_rotation_old = bodies[pair.body].rotation;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new;
      c.ft_old = c.ft_new;
      c.allowance = c.allowance_new;
    }
  }
}

void PenaltyContact::add_spring_stiffness(const Vector& x_overlap, Vector& y_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto x = x_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto y = y_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      if (!(c.k_per_area > 0)) continue;
      const double k = c.k_per_area * contact::largest_facing_area(c.sides);
      const auto at = c.row.position(x, udim);  // X + sum_I phi_I x_I
      double F[3] = {0, 0, 0};
      for (std::size_t i = 0; i < udim; ++i) F[i] = k * (at[i] - c.row.X[i]);
      c.row.spread(F, udim, y);
    }
}

std::size_t PenaltyContact::penetration_slot(const Pair& pair) const {
  return pair.contact >= 0 ? static_cast<std::size_t>(pair.contact)
                           : model_.scene.contacts.size() + static_cast<std::size_t>(pair.wall);
}

std::vector<double> PenaltyContact::take_penetrations() {
  std::vector<double> out(model_.scene.contacts.size() + model_.scene.rigid_walls.size(), 0.0);
  for (auto& pair : pairs_) {
    out[penetration_slot(pair)] = pair.peak;
    pair.peak = 0;
  }
  return out;
}

std::vector<std::vector<double>> PenaltyContact::allowances() const {
  // Contacts not in this stage hand on what they were given (a contact of stages 1 and 3).
  auto out = carried_allowances_;
  out.resize(model_.scene.contacts.size());
  for (const auto& pair : pairs_)
    if (pair.contact >= 0) {
      auto& depths = out[static_cast<std::size_t>(pair.contact)];
      depths.clear();
      for (const auto& c : pair.candidates) depths.push_back(c.allowance);
    }
  return out;
}

void PenaltyContact::carry_allowances(const std::vector<std::vector<double>>& allowances) {
  carried_allowances_ = allowances;
  for (auto& pair : pairs_) {
    if (pair.contact < 0 || static_cast<std::size_t>(pair.contact) >= allowances.size()) continue;
    const auto& depths = allowances[static_cast<std::size_t>(pair.contact)];
    if (depths.size() != pair.candidates.size()) continue;  // not active in the earlier stage
    for (std::size_t k = 0; k < depths.size(); ++k)
      pair.candidates[k].allowance = pair.candidates[k].allowance_new = depths[k];
  }
}

std::vector<double> PenaltyContact::stage_penetrations() const {
  std::vector<double> out(model_.scene.contacts.size() + model_.scene.rigid_walls.size(), 0.0);
  for (const auto& pair : pairs_) out[penetration_slot(pair)] = pair.stage_peak;
  return out;
}

long long PenaltyContact::active_count() const {
  return contact::active_over_ranks(*comm_, pairs_);
}

long long PenaltyContact::candidate_count() const {
  return contact::candidates_over_ranks(*comm_, pairs_);
}

}  // namespace efg
