#include "contact/PenaltyContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "discretization/SmoothingFacets.hpp"

namespace efg {

double PenaltyContact::largest_penalty(const Scene& scene) {
  double p = 0;
  for (const auto& c : scene.contacts) p = std::max(p, c.penalty);
  return p;
}

PenaltyContact::PenaltyContact(const ModelOperators& ops, const Vector& mass_owned,
                               const RigidBodies& bodies)
    : dim_(ops.model().mesh.dimension),
      bodies_(bodies),
      comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto& mesh = model.mesh;
  const auto udim = static_cast<std::size_t>(dim_);
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  // Candidate: owned particle j of part p, with its mass and shape-function row.
  auto candidate = [&](std::size_t p, std::size_t j) {
    const auto& part = model.parts[p];
    Candidate c;
    for (std::size_t k = 0; k < udim; ++k) c.X[k] = part.cloud.x(j)[k];
    c.mass = mass(static_cast<std::size_t>(model.maps.owned_dofs->getLocalElement(
                      static_cast<GlobalOrdinal>(part.cloud.mesh_node[j]) * dim_)),
                  0);
    for (auto k = part.particle_values.offsets[j]; k < part.particle_values.offsets[j + 1]; ++k) {
      c.nodes.push_back(
          ops.solid().overlap_node(p)[static_cast<std::size_t>(part.particle_values.particles[k])]);
      c.phi.push_back(part.particle_values.values[k]);
    }
    return c;
  };
  for (const auto& spec : model.scene.contacts) {
    Pair pair;
    for (std::size_t b = 0; b < bodies.scene_count(); ++b)
      if (bodies.name(b) == spec.rigid_body) pair.body = b;
    pair.penalty = spec.penalty;
    pair.mu_s = spec.static_friction;
    pair.mu_d = spec.dynamic_friction;
    pair.decay = spec.decay;
    pair.damping = spec.damping;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      // Surface particles: the nodes of the part's boundary sides.
      std::vector<char> on_surface(mesh.node_count(), 0);
      for (const auto& [cell, side] : boundary_sides(mesh, part.part->blocks))
        for (auto n : mesh.side_node_indices(cell, side))
          on_surface[static_cast<std::size_t>(n)] = 1;
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
    pair.wall = true;
    std::vector<char> in_set(mesh.node_count(), spec.node_set.empty() ? 1 : 0);
    if (!spec.node_set.empty())
      for (auto n : mesh.find_node_set(spec.node_set)->nodes)
        in_set[static_cast<std::size_t>(n)] = 1;
    for (std::size_t p = 0; p < model.parts.size(); ++p)
      for (std::size_t j = 0; j < model.parts[p].cloud.owned_count; ++j)
        if (in_set[static_cast<std::size_t>(model.parts[p].cloud.mesh_node[j])])
          pair.candidates.push_back(candidate(p, j));
    pairs_.push_back(std::move(pair));
  }
}

std::array<double, 3> PenaltyContact::position(const Candidate& c, const Vector& d_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::array<double, 3> x = c.X;
  for (std::size_t a = 0; a < c.nodes.size(); ++a)
    for (std::size_t k = 0; k < udim; ++k)
      x[k] += c.phi[a] * d(static_cast<std::size_t>(c.nodes[a]) * udim + k, 0);
  return x;
}

void PenaltyContact::start(const Vector& d_overlap, const std::vector<RigidBodyState>& bodies) {
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new = position(c, d_overlap);
      c.ft_old = c.ft_new = {0.0, 0.0, 0.0};
    }
  }
}

void PenaltyContact::add_forces(const Vector& d_overlap, double dt,
                                std::vector<RigidBodyState>& bodies, Vector& f_overlap) {
  const auto udim = static_cast<std::size_t>(dim_);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  // Per body: the force on it (dim) and the mass of its touching particles x penalty.
  // Per body: the force on it (3), penalty x the mass of its touching particles, and the total
  // normal force (the rigid walls' history column).
  const std::size_t nb = bodies_.count();
  std::vector<double> local(5 * nb, 0.0), total(5 * nb, 0.0);
  for (auto& pair : pairs_) {
    const auto& shape = bodies_.shape(pair.body);
    const auto& u_body = bodies[pair.body].displacement;
    const double k_per_mass = pair.penalty / (dt * dt);
    for (auto& c : pair.candidates) {
      c.x_new = position(c, d_overlap);
      const auto near = contact::proximity(shape, c.x_new.data(), u_body.data());
      c.active = near.gap < 0;
      if (!c.active) {
        c.ft_new = {0.0, 0.0, 0.0};
        continue;
      }
      const double k = k_per_mass * c.mass;
      double v_n = 0;  // approach speed along the normal, relative to the body, over the step
      for (std::size_t i = 0; i < udim; ++i)
        v_n += ((c.x_new[i] - c.x_old[i]) - (u_body[i] - pair.body_u_old[i])) * near.normal[i];
      v_n /= dt;
      const double fn =
          std::max(0.0, -k * near.gap - 2.0 * pair.damping * std::sqrt(k * c.mass) * v_n);
      std::array<double, 3> F{};
      for (std::size_t i = 0; i < udim; ++i) F[i] = fn * near.normal[i];
      if (pair.mu_s > 0 || pair.mu_d > 0) {
        // Tangential slip increment relative to the body, and the old tangential force turned
        // into the new tangent plane.
        double s[3] = {0, 0, 0}, s_n = 0, ft_n = 0;
        for (std::size_t i = 0; i < udim; ++i) {
          s[i] = (c.x_new[i] - c.x_old[i]) - (u_body[i] - pair.body_u_old[i]);
          s_n += s[i] * near.normal[i];
          ft_n += c.ft_old[i] * near.normal[i];
        }
        double ft[3] = {0, 0, 0}, ft2 = 0, slip2 = 0;
        for (std::size_t i = 0; i < udim; ++i) {
          const double st = s[i] - s_n * near.normal[i];
          slip2 += st * st;
          ft[i] = c.ft_old[i] - ft_n * near.normal[i] - k * st;
          ft2 += ft[i] * ft[i];
        }
        const double mu =
            pair.mu_d + (pair.mu_s - pair.mu_d) * std::exp(-pair.decay * std::sqrt(slip2) / dt);
        const double limit = mu * fn, size = std::sqrt(ft2);
        const double scale = size > limit ? limit / size : 1.0;
        for (std::size_t i = 0; i < udim; ++i) {
          c.ft_new[i] = ft[i] * scale;
          F[i] += c.ft_new[i];
        }
      }
      for (std::size_t a = 0; a < c.nodes.size(); ++a)
        for (std::size_t i = 0; i < udim; ++i)
          f(static_cast<std::size_t>(c.nodes[a]) * udim + i, 0) += c.phi[a] * F[i];
      for (std::size_t i = 0; i < udim; ++i) local[5 * pair.body + i] -= F[i];
      local[5 * pair.body + 3] += pair.penalty * c.mass;
      local[5 * pair.body + 4] += fn;
    }
  }
  if (nb > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
  wall_forces_.assign(nb - bodies_.scene_count(), 0.0);
  for (std::size_t b = 0; b < nb; ++b) {
    for (std::size_t i = 0; i < 3; ++i) bodies[b].force[i] = total[5 * b + i];
    if (b >= bodies_.scene_count()) wall_forces_[b - bodies_.scene_count()] = total[5 * b + 4];
    // A free body's own contact frequency: omega^2 dt^2 = sum k_J dt^2 / M = penalty sum m_J / M;
    // central differences need it below 4, kept below 1 with the particles' share.
    if (bodies_.is_free(b) && total[5 * b + 3] > bodies_.mass(b)) {
      std::ostringstream o;
      o << "rigid body '" << bodies_.name(b) << "' (mass " << bodies_.mass(b)
        << ") is too light for its contact: penalty x the mass of the particles it touches is "
        << total[5 * b + 3] << "; its contact would be unstable at this time step (give it more "
        << "mass or lower the contact's penalty)";
      throw NumericalError(o.str());
    }
  }
}

void PenaltyContact::commit(const std::vector<RigidBodyState>& bodies) {
  for (auto& pair : pairs_) {
    pair.body_u_old = bodies[pair.body].displacement;
    for (auto& c : pair.candidates) {
      c.x_old = c.x_new;
      c.ft_old = c.ft_new;
    }
  }
}

long long PenaltyContact::active_count() const {
  long long mine = 0, all = 0;
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) mine += c.active ? 1 : 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  return all;
}

}  // namespace efg

namespace efg {

long long PenaltyContact::candidate_count() const {
  long long mine = 0, all = 0;
  for (const auto& pair : pairs_) mine += static_cast<long long>(pair.candidates.size());
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, mine, Teuchos::outArg(all));
  return all;
}

}  // namespace efg
