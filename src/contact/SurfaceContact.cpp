#include "contact/SurfaceContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>

#include "contact/CandidateCounts.hpp"
#include "contact/FacetChoice.hpp"

namespace efg {

namespace {
const double* at3(const std::vector<double>& v, std::size_t node) {
  return &v[3 * node];
}
}  // namespace

bool SurfaceContact::wanted(const Scene& scene) {
  return std::any_of(scene.contacts.begin(), scene.contacts.end(),
                     [](const ContactSpec& c) { return !c.target_parts.empty(); });
}

SurfaceContact::Surface SurfaceContact::make_surface(const ModelOperators& ops,
                                                     const std::vector<std::string>& parts) const {
  const auto& model = ops.model();
  Surface surface;
  surface.facets = surface_facets(model, parts);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    if (std::find(parts.begin(), parts.end(), part.part->name) == parts.end()) continue;
    for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
      const int node = surface_node_of(
          surface.facets,
          model.mesh.global_node(static_cast<std::size_t>(part.cloud.mesh_node[j])));
      if (node < 0) continue;
      surface.rows.push_back(particle_row(ops, p, j));
      surface.row_node.push_back(node);
      surface.particle.push_back({p, j});
    }
  }
  const std::size_t nodes = surface.facets.node_id.size();
  surface.x.assign(3 * nodes, 0.0);
  surface.x_old = surface.normal = surface.x;
  return surface;
}

SurfaceContact::SurfaceContact(const ModelOperators& ops, const Vector& mass_owned,
                               const std::string& stage)
    : dim_(ops.model().mesh.dimension), comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::size_t index = 0;
  for (const auto& spec : model.scene.contacts) {
    if (spec.target_parts.empty()) continue;
    const std::size_t contact = index++;
    if (!spec.stages.includes(stage)) continue;
    // The candidates of the surface `from` against the surface `to` (two-way, also the reverse).
    const std::size_t parts = surfaces_.size(), targets = parts + 1;
    surfaces_.push_back(make_surface(ops, spec.parts));
    surfaces_.push_back(make_surface(ops, spec.target_parts));
    auto add_pair = [&](std::size_t from, std::size_t to, double sign) {
      Pair pair;
      pair.contact = contact;
      pair.sign = sign;
      pair.penalty = spec.penalty;
      // The damping is a fraction of critical for the relative motion of two facing particles
      // of equal mass m (reduced mass m / 2): one-way one spring k and damper c, c = sqrt(2)
      // damping sqrt(k m); two-way two of each, c = damping sqrt(k m) (pair.damping holds the
      // factor of sqrt(k m)).
      pair.damping = spec.damping * (spec.two_way ? 1.0 : std::sqrt(2.0));
      pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
      pair.own = from;
      pair.target = to;
      const auto& own = surfaces_[from];
      for (std::size_t row = 0; row < own.rows.size(); ++row) {
        Candidate c;
        c.row = row;
        c.mass = particle_mass(model, mass, own.particle[row][0], own.particle[row][1]);
        pair.candidates.push_back(c);
      }
      pair.reaction = surfaces_[to].x;
      pairs_.push_back(std::move(pair));
    };
    add_pair(parts, targets, 1.0);
    if (spec.two_way) add_pair(targets, parts, -1.0);
  }
  forces_.assign(3 * index, 0.0);
}

// Positions of every surface node (each owned by one rank: the sum over ranks is a gather,
// exact), then the nodal normals: the sum of the adjacent facets' normals scaled by their
// length (2D) or twice their area (3D), normalized.
void SurfaceContact::gather(Surface& surface, const Vector& d_overlap) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  auto& mine = surface.mine;
  mine.assign(surface.x.size(), 0.0);
  for (std::size_t r = 0; r < surface.rows.size(); ++r) {
    const auto x = surface.rows[r].position(d, udim);
    std::copy(x.begin(), x.end(),
              mine.begin() + 3 * static_cast<std::ptrdiff_t>(surface.row_node[r]));
  }
  if (!mine.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(mine.size()), mine.data(),
                       surface.x.data());
  contact::nodal_normals(surface.facets.facet, surface.facets.nodes_per_facet, surface.x, dim_,
                         surface.normal);
}

// Each facet's box grown by its capture region (contact::facet_capture_box; grown by the
// capture depth in every direction, a 3D block's face listed about 100 facets per bin).
// Refreshed as needed: while no target node has moved by more than the margin since the last
// build, every facet is still inside its box (Verlet-list reasoning), so the bins stand.
void SurfaceContact::build_bins(Pair& pair) const {
  const auto& target = surfaces_[pair.target];
  const auto& s = target.facets;
  if (!pair.x_binned.empty()) {
    double moved = 0;
    for (std::size_t i = 0; i < target.x.size(); i += 3) {
      double d2 = 0;
      for (std::size_t k = 0; k < 3; ++k)
        d2 += (target.x[i + k] - pair.x_binned[i + k]) * (target.x[i + k] - pair.x_binned[i + k]);
      moved = std::max(moved, d2);
    }
    if (std::sqrt(moved) <= pair.bin_margin) return;
  }
  const auto d = static_cast<std::size_t>(dim_);
  pair.lower.assign(d * s.count(), 0.0);
  pair.upper.assign(d * s.count(), 0.0);
  double edge = 0, smallest = 0;
  for (std::size_t f = 0; f < s.count(); ++f)
    smallest = f == 0 ? s.reference_size[f] : std::min(smallest, s.reference_size[f]);
  pair.bin_margin = 0.1 * smallest;
  for (std::size_t f = 0; f < s.count(); ++f) {
    double corner[3][3] = {};
    target.corners(f, corner);
    edge = std::max(
        edge, contact::facet_capture_box(corner, s.nodes_per_facet, dim_, s.reference_size[f],
                                         pair.bin_margin, &pair.lower[f * d], &pair.upper[f * d]));
  }
  pair.bins.build(dim_, pair.lower, pair.upper, edge);
  pair.x_binned = target.x;
}

// The facet a candidate presses into: its facet of the last accepted step while it still lies
// over it, inside and not deeper than the facet's size (contact history, as node-to-segment
// codes track their master segment); otherwise, among the facets facing its own surface
// (kFacing) that it lies over and is inside of, the one nearest along its normal.
std::pair<int, contact::FacetPoint> SurfaceContact::choose_facet(const Pair& pair,
                                                                 const Candidate& c) const {
  const auto& own = surfaces_[pair.own];
  const auto& target = surfaces_[pair.target];
  const auto node = static_cast<std::size_t>(own.row_node[c.row]);
  return contact::choose_facet(
      at3(own.x, node), at3(own.normal, node), c.facet_old, pair.bins, target.facets.reference_size,
      dim_, [&](std::size_t f, double(&corner)[3][3]) { target.corners(f, corner); });
}

void SurfaceContact::start(const Vector& d_overlap) {
  for (auto& surface : surfaces_) {
    gather(surface, d_overlap);
    surface.x_old = surface.x;
  }
  for (auto& pair : pairs_) {
    for (auto& c : pair.candidates) {
      c.ft_old = c.ft_new = {0.0, 0.0, 0.0};
      c.facet = c.facet_old = -1;
    }
  }
}

void SurfaceContact::add_forces(const Vector& d_overlap, double dt, Vector& f_overlap) {
  const auto udim = static_cast<std::size_t>(dim_);
  std::vector<double> local(forces_.size(), 0.0);
  for (auto& surface : surfaces_) gather(surface, d_overlap);
  for (auto& pair : pairs_) {
    build_bins(pair);
    const auto& own = surfaces_[pair.own];
    const auto& target = surfaces_[pair.target];
    const auto& s = target.facets;
    const auto per = static_cast<std::size_t>(s.nodes_per_facet);
    std::fill(pair.reaction.begin(), pair.reaction.end(), 0.0);
    const double k_per_mass = pair.penalty / (dt * dt);
    const bool friction = pair.friction.mu_s > 0 || pair.friction.mu_d > 0;
    auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (auto& c : pair.candidates) {
      const auto [best_facet, best] = choose_facet(pair, c);
      c.active = best_facet >= 0;
      c.facet = best_facet;
      if (!c.active) {
        c.ft_new = {0.0, 0.0, 0.0};
        continue;
      }
      const auto facet = static_cast<std::size_t>(best_facet);
      const auto node = static_cast<std::size_t>(own.row_node[c.row]);
      const double k = k_per_mass * c.mass;
      // The particle's motion relative to the facet's point over the step: its normal part is
      // the approach (damping), its tangential part the slip (friction).
      double s_rel[3] = {0, 0, 0}, v_n = 0;
      for (std::size_t i = 0; i < udim; ++i) {
        double facet_motion = 0;
        for (std::size_t a = 0; a < per; ++a) {
          const auto n = 3 * static_cast<std::size_t>(s.facet[facet * per + a]) + i;
          facet_motion += best.weight[a] * (target.x[n] - target.x_old[n]);
        }
        s_rel[i] = (own.x[3 * node + i] - own.x_old[3 * node + i]) - facet_motion;
        v_n += s_rel[i] * best.normal[i] / dt;
      }
      const double fn = std::max(0.0, -k * best.gap - pair.damping * std::sqrt(k * c.mass) * v_n);
      double F[3] = {0, 0, 0};
      for (std::size_t i = 0; i < udim; ++i) F[i] = fn * best.normal[i];
      if (friction) {
        contact::coulomb_return(pair.friction, c.ft_old.data(), s_rel, best.normal, k, fn, dt, dim_,
                                c.ft_new.data());
        for (std::size_t i = 0; i < udim; ++i) F[i] += c.ft_new[i];
      }
      own.rows[c.row].spread(F, udim, f);
      for (std::size_t a = 0; a < per; ++a)
        for (std::size_t i = 0; i < udim; ++i)
          pair.reaction[3 * static_cast<std::size_t>(s.facet[facet * per + a]) + i] -=
              best.weight[a] * F[i];
      // The force on the target parts: the reaction when the candidates are the parts'.
      for (std::size_t i = 0; i < udim; ++i) local[3 * pair.contact + i] -= pair.sign * F[i];
    }
    // The reactions reach the surface particles' owners, which spread them through their rows.
    auto& reaction = pair.reaction_sum;
    reaction.resize(pair.reaction.size());
    if (!reaction.empty())
      Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(reaction.size()),
                         pair.reaction.data(), reaction.data());
    for (std::size_t r = 0; r < target.rows.size(); ++r)
      target.rows[r].spread(at3(reaction, static_cast<std::size_t>(target.row_node[r])), udim, f);
  }
  if (!forces_.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       forces_.data());
}

void SurfaceContact::commit() {
  for (auto& surface : surfaces_) surface.x_old = surface.x;
  for (auto& pair : pairs_) {
    for (auto& c : pair.candidates) {
      c.ft_old = c.ft_new;
      c.facet_old = c.facet;
    }
  }
}

long long SurfaceContact::active_count() const {
  return contact::active_over_ranks(*comm_, pairs_);
}

long long SurfaceContact::candidate_count() const {
  return contact::candidates_over_ranks(*comm_, pairs_);
}

}  // namespace efg
