#include "contact/ImplicitSurfaceContact.hpp"

#include <Sacado.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <stdexcept>

#include "contact/BoundaryShares.hpp"
#include "contact/FacetChoice.hpp"
#include "contact/PairPenalty.hpp"
#include "model/ContactGhosts.hpp"

namespace efg {

namespace {
// Forward AD over a pair's points: the particle and up to 3 facet nodes, 3 components each.
using PairFad = Sacado::Fad::SFad<double, 12>;

bool in_parts(const std::vector<std::string>& parts, const std::string& name) {
  return std::find(parts.begin(), parts.end(), name) != parts.end();
}
}  // namespace

bool ImplicitSurfaceContact::wanted(const Scene& scene) {
  return std::any_of(scene.contacts.begin(), scene.contacts.end(),
                     [&](const ContactSpec& c) { return acts_between_parts_implicitly(scene, c); });
}

void ImplicitSurfaceContact::Surface::corners(std::size_t f, double (&corner)[3][3]) const {
  const auto per = static_cast<std::size_t>(facets.nodes_per_facet);
  for (std::size_t a = 0; a < per; ++a)
    for (std::size_t k = 0; k < 3; ++k)
      corner[a][k] = x[3 * static_cast<std::size_t>(facets.facet[f * per + a]) + k];
}

// The rows of every surface particle on every rank: each owner contributes its rows (global
// node ids, values, reference position) to a sum over ranks in a layout all ranks agree on
// (row lengths first), then the ids become overlap ids - all of them ghosts here, remote ones
// included (model/ContactGhosts), or the model was built without them: a bug, said so.
ImplicitSurfaceContact::Surface ImplicitSurfaceContact::make_surface(
    const ModelOperators& ops, const std::vector<std::string>& parts) const {
  const auto& model = ops.model();
  Surface s;
  s.facets = surface_facets(model, parts);
  // the surface node of each mesh node here (on a rank's part of a mesh read in slices the
  // surface's nodes beyond the part have none: their owners give their rows)
  const std::size_t nodes = s.facets.node_id.size();
  std::vector<int> index(model.mesh.node_count(), -1);
  for (std::size_t n = 0; n < nodes; ++n) {
    const auto local = model.mesh.node_of(s.facets.node_id[n]);
    if (local >= 0) index[static_cast<std::size_t>(local)] = static_cast<int>(n);
  }
  std::vector<ParticleRow> mine(nodes);
  std::vector<int> length(nodes, 0), lengths(nodes, 0);
  for (std::size_t p = 0; p < model.parts.size(); ++p) {
    const auto& part = model.parts[p];
    if (!in_parts(parts, part.part->name)) continue;
    for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
      const int n = index[static_cast<std::size_t>(part.cloud.mesh_node[j])];
      if (n < 0 || length[static_cast<std::size_t>(n)] > 0) continue;
      mine[static_cast<std::size_t>(n)] = particle_row(ops, p, j);
      length[static_cast<std::size_t>(n)] =
          static_cast<int>(mine[static_cast<std::size_t>(n)].nodes.size());
    }
  }
  const auto& comm = *comm_;
  if (nodes > 0)
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(nodes), length.data(),
                       lengths.data());
  std::vector<std::size_t> offset(nodes + 1, 0);
  for (std::size_t n = 0; n < nodes; ++n)
    offset[n + 1] = offset[n] + static_cast<std::size_t>(lengths[n]);
  const auto& overlap = *model.maps.overlap_nodes;
  std::vector<long long> gid(offset[nodes], 0), gids(gid.size(), 0);
  std::vector<double> value(offset[nodes] + 3 * nodes, 0.0), values(value.size(), 0.0);
  for (std::size_t n = 0; n < nodes; ++n) {
    const auto& row = mine[n];
    for (std::size_t a = 0; a < row.nodes.size(); ++a) {
      gid[offset[n] + a] = static_cast<long long>(overlap.getGlobalElement(row.nodes[a]));
      value[offset[n] + a] = row.phi[a];
    }
    if (length[n] > 0)
      for (std::size_t k = 0; k < 3; ++k) value[offset[nodes] + 3 * n + k] = row.X[k];
  }
  if (!gid.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(gid.size()), gid.data(),
                       gids.data());
  if (!value.empty())
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(value.size()), value.data(),
                       values.data());
  s.rows.resize(nodes);
  for (std::size_t n = 0; n < nodes; ++n) {
    auto& row = s.rows[n];
    for (std::size_t k = 0; k < 3; ++k) row.X[k] = values[offset[nodes] + 3 * n + k];
    for (std::size_t e = offset[n]; e < offset[n + 1]; ++e) {
      const auto lid = overlap.getLocalElement(static_cast<GlobalOrdinal>(gids[e]));
      if (lid == Teuchos::OrdinalTraits<Map::local_ordinal_type>::invalid())
        throw std::logic_error("implicit contact between parts: a surface row's node " +
                               std::to_string(gids[e]) + " is not a ghost of this rank");
      row.nodes.push_back(static_cast<int>(lid));
      row.phi.push_back(values[e]);
    }
  }
  s.x.assign(3 * nodes, 0.0);
  s.normal = s.x;
  s.x_old.reserve(3 * nodes);  // the reference configuration until a stage starts
  for (const auto& row : s.rows) s.x_old.insert(s.x_old.end(), row.X.begin(), row.X.end());
  return s;
}

ImplicitSurfaceContact::ImplicitSurfaceContact(const ModelOperators& ops)
    : dim_(ops.model().mesh.dimension), comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto& owner = model.partition.owner;
  for (const auto& spec : model.scene.contacts) {
    if (spec.target_parts.empty()) continue;
    const std::size_t contact = contact_count_++;
    if (!acts_between_parts_implicitly(model.scene, spec)) continue;
    const std::size_t parts = surfaces_.size(), targets = parts + 1;
    surfaces_.push_back(make_surface(ops, spec.parts));
    surfaces_.push_back(make_surface(ops, spec.target_parts));
    auto add_pair = [&](std::size_t from, std::size_t to, double sign,
                        const std::vector<std::string>& names) {
      Pair pair;
      pair.contact = contact;
      pair.spec = &spec;
      pair.sign = sign;
      pair.own = from;
      pair.target = to;
      pair.active = true;  // until a stage says otherwise (begin_stage)
      pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
      const auto& own = surfaces_[from];
      // Each candidate's penalty from its own part (the first of the names holding it).
      std::vector<double> k(model.mesh.node_count(), 0.0);
      for (std::size_t p = model.parts.size(); p-- > 0;) {
        if (!in_parts(names, model.parts[p].part->name)) continue;
        const double E = part_youngs_modulus(model, p);
        const auto shares = part_boundary_shares(model, p);
        for (std::size_t n = 0; n < k.size(); ++n)
          if (shares.area[n] > 0) k[n] = penalty_stiffness(shares, n, spec.implicit_penalty, E);
      }
      for (std::size_t n = 0; n < own.facets.node_id.size(); ++n) {
        const auto local = model.mesh.node_of(own.facets.node_id[n]);
        if (local < 0) continue;  // beyond this rank's part of the mesh: owned elsewhere
        const auto node = static_cast<std::size_t>(local);
        if (owner[node] != model.partition.rank) continue;
        Candidate c;
        c.node = n;
        c.stiffness = k[node];
        pair.candidates.push_back(c);
      }
      pairs_.push_back(std::move(pair));
    };
    add_pair(parts, targets, 1.0, spec.parts);
    if (spec.two_way) add_pair(targets, parts, -1.0, spec.target_parts);
  }
}

void ImplicitSurfaceContact::begin_stage(const std::string& stage, const Vector& d_overlap,
                                         double t0) {
  t_ = t0;
  evaluate(d_overlap, 0.0);
  for (auto& s : surfaces_) s.x_old = s.x;
  for (auto& pair : pairs_) {
    pair.active = pair.spec->stages.includes(stage);
    for (auto& c : pair.candidates) {
      c.facet_old = -1;
      for (double& f : c.ft_old) f = 0.0;
    }
  }
  t_committed_ = t_;
}

const contact::PairFriction* ImplicitSurfaceContact::friction_of(const Pair& pair,
                                                                 const Candidate& c, int facet,
                                                                 double (&corner_old)[3][3],
                                                                 contact::PairFriction& out) const {
  if (!pair.rubs()) return nullptr;
  const auto& target = surfaces_[pair.target];
  const auto per = static_cast<std::size_t>(target.facets.nodes_per_facet);
  for (std::size_t a = 0; a < per; ++a)
    for (std::size_t k = 0; k < 3; ++k)
      corner_old[a][k] =
          target.x_old[3 * static_cast<std::size_t>(
                               target.facets.facet[static_cast<std::size_t>(facet) * per + a]) +
                       k];
  out.law = pair.friction;
  out.x_old = &surfaces_[pair.own].x_old[3 * c.node];
  out.corner_old = corner_old;
  out.ft_old = c.ft_old;
  out.stick_stiffness = c.stiffness / pair.spec->implicit_penalty;
  out.dt = t_ > t_committed_ ? t_ - t_committed_ : 1.0;  // the decay law's rate
  return &out;
}

void ImplicitSurfaceContact::evaluate(const Vector& d_overlap, double reach) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto udim = static_cast<std::size_t>(dim_);
  for (auto& s : surfaces_) {
    for (std::size_t n = 0; n < s.rows.size(); ++n) {
      const auto x = s.rows[n].position(d, udim);
      std::copy(x.begin(), x.end(), s.x.begin() + 3 * static_cast<std::ptrdiff_t>(n));
    }
    contact::nodal_normals(s.facets.facet, s.facets.nodes_per_facet, s.x, dim_, s.normal);
  }
  std::vector<double> lower, upper;
  for (const auto& pair : pairs_) {
    if (!pair.active) continue;
    const auto& target = surfaces_[pair.target];
    const auto& f = target.facets;
    lower.assign(udim * f.count(), 0.0);
    upper.assign(udim * f.count(), 0.0);
    double edge = 0;
    for (std::size_t k = 0; k < f.count(); ++k) {
      double corner[3][3] = {};
      target.corners(k, corner);
      edge = std::max(edge, contact::facet_capture_box(
                                corner, f.nodes_per_facet, dim_, f.reference_size[k],
                                reach * f.reference_size[k], &lower[k * udim], &upper[k * udim]));
    }
    pair.bins.build(dim_, lower, upper, edge);
  }
}

ImplicitSurfaceContact::Press ImplicitSurfaceContact::press(const Pair& pair,
                                                            const Candidate& c) const {
  const auto& own = surfaces_[pair.own];
  const auto& target = surfaces_[pair.target];
  const auto corners = [&](std::size_t f, double(&corner)[3][3]) { target.corners(f, corner); };
  // The explicit capture depth of one facet size: 4 sizes did not speed up Newton on the Hertz
  // cylinders and caught a block's far side through a corner particle's diagonal normal.
  const auto [facet, point] =
      contact::choose_facet(&own.x[3 * c.node], &own.normal[3 * c.node], c.facet_old, pair.bins,
                            target.facets.reference_size, dim_, corners);
  Press p;
  p.facet = facet;
  if (facet < 0) return p;
  double corner[3][3] = {}, corner_old[3][3] = {};
  corners(static_cast<std::size_t>(facet), corner);
  contact::PairFriction friction;
  contact::pair_penalty_forces(&own.x[3 * c.node], corner, dim_, c.stiffness, p.force,
                               friction_of(pair, c, facet, corner_old, friction), p.ft);
  return p;
}

std::vector<const ParticleRow*> ImplicitSurfaceContact::rows_of(const Pair& pair,
                                                                const Candidate& c,
                                                                int facet) const {
  const auto& target = surfaces_[pair.target];
  const auto per = static_cast<std::size_t>(target.facets.nodes_per_facet);
  std::vector<const ParticleRow*> rows{&surfaces_[pair.own].rows[c.node]};
  for (std::size_t a = 0; a < per; ++a)
    rows.push_back(&target.rows[static_cast<std::size_t>(
        target.facets.facet[static_cast<std::size_t>(facet) * per + a])]);
  return rows;
}

bool ImplicitSurfaceContact::refresh_couplings(const Vector& d_overlap) {
  evaluate(d_overlap, 1.0);  // bins grown by one facet size beyond the capture boxes
  int grew = 0, any = 0;
  for (auto& pair : pairs_) {
    if (!pair.active) continue;
    const auto& own = surfaces_[pair.own];
    for (auto& c : pair.candidates) {
      const auto [begin, end] = pair.bins.near(&own.x[3 * c.node]);
      for (const int* it = begin; it != end; ++it)
        if (!std::binary_search(c.coupled.begin(), c.coupled.end(), *it)) {
          c.coupled.insert(std::upper_bound(c.coupled.begin(), c.coupled.end(), *it), *it);
          grew = 1;
        }
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, grew, Teuchos::outArg(any));
  return any != 0;
}

void ImplicitSurfaceContact::add_couplings(CouplingGraph& graph) const {
  std::vector<int> nodes;
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates)
      for (int facet : c.coupled) {
        nodes.clear();
        for (const auto* row : rows_of(pair, c, facet))
          nodes.insert(nodes.end(), row->nodes.begin(), row->nodes.end());
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        graph.add_clique(nodes.data(), nodes.size());
      }
}

void ImplicitSurfaceContact::add_residual(const Vector& d_overlap, Vector& r_overlap) const {
  evaluate(d_overlap, 0.0);
  const auto udim = static_cast<std::size_t>(dim_);
  auto r = r_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& pair : pairs_) {
    if (!pair.active) continue;
    for (const auto& c : pair.candidates) {
      const auto p = press(pair, c);
      if (p.facet < 0) continue;
      const auto rows = rows_of(pair, c, p.facet);
      for (std::size_t P = 0; P < rows.size(); ++P) {
        const double minus_F[3] = {-p.force[P][0], -p.force[P][1], -p.force[P][2]};
        rows[P]->spread(minus_F, udim, r);
      }
    }
  }
}

void ImplicitSurfaceContact::add_tangent(const Vector& d_overlap, FEMatrix& K) const {
  evaluate(d_overlap, 0.0);
  const auto udim = static_cast<std::size_t>(dim_);
  std::vector<int> nodes, cols;
  std::vector<double> vals;
  for (const auto& pair : pairs_) {
    if (!pair.active) continue;
    const auto& own = surfaces_[pair.own];
    const auto& target = surfaces_[pair.target];
    for (const auto& c : pair.candidates) {
      const auto p = press(pair, c);
      if (p.facet < 0) continue;
      // dF_P/dx_Q of the pair's points by forward AD: seed x_Q's component j as derivative
      // Q dim + j.
      const auto rows = rows_of(pair, c, p.facet);
      const std::size_t points = rows.size();
      PairFad x[3], corner[3][3], force[4][3];
      double corner_x[3][3] = {};
      target.corners(static_cast<std::size_t>(p.facet), corner_x);
      for (std::size_t i = 0; i < 3; ++i) {
        x[i] = own.x[3 * c.node + i];
        if (i < udim) x[i].diff(static_cast<int>(i), 12);
        for (std::size_t a = 0; a + 1 < points; ++a) {
          corner[a][i] = corner_x[a][i];
          if (i < udim) corner[a][i].diff(static_cast<int>((a + 1) * udim + i), 12);
        }
      }
      double corner_old[3][3] = {};
      contact::PairFriction friction;
      contact::pair_penalty_forces<PairFad>(x, corner, dim_, c.stiffness, force,
                                            friction_of(pair, c, p.facet, corner_old, friction));
      // K_(I i),(K j) += phi_P,I (-dF_P,i / dx_Q,j) phi_Q,K, one column per node K (the
      // facet's nodes share rows: their entries are summed here, once per column).
      nodes.clear();
      for (std::size_t Q = 0; Q < points; ++Q)
        nodes.insert(nodes.end(), rows[Q]->nodes.begin(), rows[Q]->nodes.end());
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      cols.clear();
      for (int n : nodes)
        for (std::size_t j = 0; j < udim; ++j) cols.push_back(n * dim_ + static_cast<int>(j));
      vals.resize(cols.size());
      for (std::size_t P = 0; P < points; ++P)
        for (std::size_t a = 0; a < rows[P]->nodes.size(); ++a)
          for (std::size_t i = 0; i < udim; ++i) {
            std::fill(vals.begin(), vals.end(), 0.0);
            for (std::size_t Q = 0; Q < points; ++Q)
              for (std::size_t b = 0; b < rows[Q]->nodes.size(); ++b) {
                const auto column = static_cast<std::size_t>(
                    std::lower_bound(nodes.begin(), nodes.end(), rows[Q]->nodes[b]) -
                    nodes.begin());
                for (std::size_t j = 0; j < udim; ++j)
                  vals[column * udim + j] -=
                      rows[P]->phi[a] * rows[Q]->phi[b] *
                      force[P][i].fastAccessDx(static_cast<int>(Q * udim + j));
              }
            const int row = rows[P]->nodes[a] * dim_ + static_cast<int>(i);
            const auto summed =
                K.sumIntoLocalValues(row, static_cast<int>(cols.size()), vals.data(), cols.data());
            dropped_ += static_cast<long long>(cols.size()) - summed;
          }
    }
  }
}

void ImplicitSurfaceContact::commit(const Vector& d_overlap) {
  evaluate(d_overlap, 0.0);
  for (auto& pair : pairs_) {
    if (!pair.active) continue;
    for (auto& c : pair.candidates) {
      const auto p = press(pair, c);
      c.facet_old = p.facet;
      for (std::size_t i = 0; i < 3; ++i) c.ft_old[i] = p.facet >= 0 ? p.ft[i] : 0.0;
    }
  }
  for (auto& s : surfaces_) s.x_old = s.x;
  t_committed_ = t_;
}

std::vector<double> ImplicitSurfaceContact::forces(const Vector& d_overlap) const {
  evaluate(d_overlap, 0.0);
  std::vector<double> local(3 * contact_count_, 0.0), total(local.size(), 0.0);
  for (const auto& pair : pairs_) {
    if (!pair.active) continue;
    for (const auto& c : pair.candidates) {
      const auto p = press(pair, c);
      if (p.facet < 0) continue;
      // The force on the target parts: the reaction when the candidates are the parts'.
      for (std::size_t i = 0; i < 3; ++i) local[3 * pair.contact + i] -= pair.sign * p.force[0][i];
    }
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
  return total;
}

}  // namespace efg
