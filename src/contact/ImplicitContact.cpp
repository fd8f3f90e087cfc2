#include "contact/ImplicitContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/BoundaryShares.hpp"
#include "contact/PenaltyForce.hpp"

namespace efg {

namespace {
// B += -dF_t/dx of the Coulomb return map (see the header): stick k_t P_t; slip
// mu (k t n^T + k_t F_n / |F_t*| (I - t t^T) P_t), k the normal and k_t the stick stiffness.
template <class Touch>
void add_friction_tangent(const Touch& t, double k, double k_t, std::size_t dim,
                          double (&B)[3][3]) {
  double P[3][3];
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) P[i][j] = (i == j ? 1.0 : 0.0) - t.normal[i] * t.normal[j];
  if (!t.coulomb.slipping) {
    for (std::size_t i = 0; i < dim; ++i)
      for (std::size_t j = 0; j < dim; ++j) B[i][j] += k_t * P[i][j];
    return;
  }
  const double mu = t.coulomb.mu, fn = -k * t.gap;
  double size = 0, dir[3] = {0, 0, 0};
  for (std::size_t i = 0; i < 3; ++i) size += t.ft[i] * t.ft[i];
  size = std::sqrt(size);
  if (size > 0)
    for (std::size_t i = 0; i < 3; ++i) dir[i] = t.ft[i] / size;
  const double ratio = t.coulomb.trial > 0 ? k_t * fn / t.coulomb.trial : 0.0;
  for (std::size_t i = 0; i < dim; ++i)
    for (std::size_t j = 0; j < dim; ++j) {
      double turn = 0;  // ((I - t t^T) P_t)_ij
      for (std::size_t m = 0; m < 3; ++m)
        turn += ((i == m ? 1.0 : 0.0) - dir[i] * dir[m]) * P[m][j];
      B[i][j] += mu * (k * dir[i] * t.normal[j] + ratio * turn);
    }
}
}  // namespace

ImplicitContact::ImplicitContact(const ModelOperators& ops)
    : dim_(ops.model().mesh.dimension),
      bodies_(ops.model().scene, ops.model().mesh.dimension),
      comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  for (const auto& spec : model.scene.contacts) {
    if (spec.rigid_body.empty()) continue;  // between deformable parts: ImplicitSurfaceContact
    Pair pair;
    pair.spec = &spec;
    pair.friction = {spec.static_friction, spec.dynamic_friction, spec.decay};
    for (std::size_t b = 0; b < bodies_.count(); ++b)
      if (bodies_.name(b) == spec.rigid_body) pair.body = b;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      const double E = part_youngs_modulus(model, p);
      const auto shares = part_boundary_shares(model, p);
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
        const auto node = static_cast<std::size_t>(part.cloud.mesh_node[j]);
        if (!(shares.area[node] > 0)) continue;  // not on the part's surface
        Candidate c;
        c.row = particle_row(ops, p, j);
        c.stiffness = penalty_stiffness(shares, node, spec.implicit_penalty, E);
        c.size = shares.size[node];
        pair.candidates.push_back(std::move(c));
      }
    }
    pairs_.push_back(std::move(pair));
  }
}

void ImplicitContact::begin_stage(const std::vector<RigidBodyState>& carried, double t0,
                                  const std::string& stage) {
  for (auto& pair : pairs_) pair.active = pair.spec->stages.includes(stage);
  t0_ = t_ = t_committed_ = t0;
  start_.assign(bodies_.count(), {0.0, 0.0, 0.0});
  start_rotation_.assign(bodies_.count(), {0.0, 0.0, 0.0});
  start_orientation_.assign(bodies_.count(), contact::identity_orientation());
  for (std::size_t b = 0; b < std::min(carried.size(), start_.size()); ++b) {
    start_[b] = carried[b].displacement;
    start_rotation_[b] = carried[b].rotation;
    start_orientation_[b] = carried[b].orientation;
  }
  displacement_ = committed_displacement_ = start_;
  rotation_ = committed_rotation_ = start_rotation_;
  orientation_ = start_orientation_;
  offset_.assign(bodies_.count(), {0.0, 0.0, 0.0});
}

void ImplicitContact::set_offset(std::size_t b, const std::array<double, 3>& u) {
  offset_[b] = u;
  set_time(t_);
}

bool ImplicitContact::has_friction() const {
  return std::any_of(pairs_.begin(), pairs_.end(), [](const Pair& p) { return rubs(p); });
}

void ImplicitContact::start_friction(const Vector& d_overlap) {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (auto& pair : pairs_)
    for (auto& c : pair.candidates) {
      c.x_old = c.row.position(d, static_cast<std::size_t>(dim_));
      c.ft_old = {0.0, 0.0, 0.0};
    }
  committed_displacement_ = displacement_;
  committed_rotation_ = rotation_;
  t_committed_ = t_;
}

void ImplicitContact::commit(const Vector& d_overlap) {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (auto& pair : pairs_) {
    if (!rubs(pair)) continue;
    for (auto& c : pair.candidates) {
      const auto t = touch(pair, c, d);
      c.x_old = c.row.position(d, static_cast<std::size_t>(dim_));
      for (std::size_t i = 0; i < 3; ++i) c.ft_old[i] = pair.active && t.gap < 0 ? t.ft[i] : 0.0;
    }
  }
  committed_displacement_ = displacement_;
  committed_rotation_ = rotation_;
  t_committed_ = t_;
}

void ImplicitContact::set_time(double t) {
  if (start_.size() != bodies_.count()) begin_stage({}, t0_);
  t_ = t;
  for (std::size_t b = 0; b < bodies_.count(); ++b) {
    const auto travel = bodies_.prescribed_travel(b, t0_, t);
    const auto turn = bodies_.prescribed_turn(b, t0_, t);
    for (std::size_t k = 0; k < 3; ++k) {
      displacement_[b][k] = start_[b][k] + travel[k] + offset_[b][k];
      rotation_[b][k] = start_rotation_[b][k] + turn[k];
    }
    orientation_[b] = contact::turned(start_orientation_[b], turn.data());
  }
}

void ImplicitContact::add_couplings(CouplingGraph& graph) const {
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) graph.add_clique(c.row.nodes.data(), c.row.nodes.size());
}

template <class View>
ImplicitContact::Touch ImplicitContact::touch(const Pair& p, const Candidate& c,
                                              const View& d) const {
  const auto x = c.row.position(d, static_cast<std::size_t>(dim_));
  const auto& shape = bodies_.shape(p.body);
  const double zero[3] = {0, 0, 0};
  const double* u_body = displacement_.empty() ? zero : displacement_[p.body].data();
  const auto near = rotation_.empty()
                        ? contact::proximity(shape, x.data(), u_body)
                        : contact::proximity_of_body(shape, x.data(), u_body, rotation_[p.body][2],
                                                     orientation_[p.body]);
  Touch t;
  t.gap = near.gap;
  for (int i = 0; i < 3; ++i) t.normal[i] = near.normal[i];
  contact::normal_derivative(shape, near, t.dn);
  if (rubs(p) && t.gap < 0) {
    // The slip since the last accepted load step: the particle's motion relative to the body.
    double s[3] = {0, 0, 0}, u_old[3] = {0, 0, 0}, turn[3] = {0, 0, 0};
    for (std::size_t i = 0; i < 3 && !committed_displacement_.empty(); ++i) {
      u_old[i] = committed_displacement_[p.body][i];
      turn[i] = rotation_[p.body][i] - committed_rotation_[p.body][i];
    }
    contact::slip_against_body(shape, x.data(), c.x_old.data(), u_body, u_old, turn, dim_, s);
    const double step = t_ > t_committed_ ? t_ - t_committed_ : 1.0;  // the decay law's rate
    t.coulomb =
        contact::coulomb_return(p.friction, c.ft_old.data(), s, t.normal, stick_stiffness(p, c),
                                -c.stiffness * t.gap, step, dim_, t.ft);
  }
  return t;
}

void ImplicitContact::add_residual(const Vector& d_overlap, Vector& r_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto r = r_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      if (!pair.active) break;  // the whole pair is out of this stage
      const auto t = touch(pair, c, d);
      if (!(t.gap < 0)) continue;
      double minus_F[3];  // r -= phi F, F = k (-g) n + F_t
      for (std::size_t i = 0; i < 3; ++i) minus_F[i] = c.stiffness * t.gap * t.normal[i] - t.ft[i];
      c.row.spread(minus_F, udim, r);
    }
}

void ImplicitContact::particle_tangent(const Pair& pair, const Candidate& c, const Touch& t,
                                       double (&B)[3][3]) const {
  // d(k g n_i)/dx_j = k (n_i n_j + g dn_ij/dx_j); x_J = X_J + sum_K phi_K d_K.
  const auto udim = static_cast<std::size_t>(dim_);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      B[i][j] = i < udim && j < udim
                    ? c.stiffness * (t.normal[i] * t.normal[j] + t.gap * t.dn[i][j])
                    : 0.0;
  if (rubs(pair)) add_friction_tangent(t, c.stiffness, stick_stiffness(pair, c), udim, B);
}

void ImplicitContact::add_tangent(const Vector& d_overlap, FEMatrix& K) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      if (!pair.active) break;  // the whole pair is out of this stage
      const auto t = touch(pair, c, d);
      if (!(t.gap < 0)) continue;
      double B[3][3];
      particle_tangent(pair, c, t, B);
      const auto& nodes = c.row.nodes;
      const auto& phi = c.row.phi;
      const std::size_t n = nodes.size();
      std::vector<int> cols(n * udim);
      std::vector<double> vals(n * udim);
      for (std::size_t b = 0; b < n; ++b)
        for (std::size_t j = 0; j < udim; ++j)
          cols[b * udim + j] = nodes[b] * dim_ + static_cast<int>(j);
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t i = 0; i < udim; ++i) {
          for (std::size_t b = 0; b < n; ++b)
            for (std::size_t j = 0; j < udim; ++j) vals[b * udim + j] = phi[a] * phi[b] * B[i][j];
          K.sumIntoLocalValues(nodes[a] * dim_ + static_cast<int>(i), static_cast<int>(cols.size()),
                               vals.data(), cols.data());
        }
    }
}

std::vector<BodyResultant> ImplicitContact::body_forces(const Vector& d_overlap) const {
  const std::size_t nb = bodies_.count();
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<double> local(6 * nb, 0.0), total(6 * nb, 0.0);  // force, moment per body
  const double zero[3] = {0, 0, 0};
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      if (!pair.active) break;  // the whole pair is out of this stage
      const auto t = touch(pair, c, d);
      if (!(t.gap < 0)) continue;
      double F[3];
      for (std::size_t i = 0; i < 3; ++i) {
        F[i] = c.stiffness * t.gap * t.normal[i] - t.ft[i];
        local[6 * pair.body + i] += F[i];
      }
      const auto x = c.row.position(d, static_cast<std::size_t>(dim_));
      contact::add_moment(bodies_.shape(pair.body),
                          displacement_.empty() ? zero : displacement_[pair.body].data(), x.data(),
                          F, &local[6 * pair.body + 3]);
    }
  if (nb > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
  std::vector<BodyResultant> out(nb);
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t i = 0; i < 3; ++i) {
      out[b].force[i] = total[6 * b + i];
      out[b].moment[i] = total[6 * b + 3 + i];
    }
  return out;
}

double ImplicitContact::body_stiffness(const Vector& d_overlap, std::size_t b,
                                       const double* a) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double local = 0, total = 0;
  for (const auto& pair : pairs_) {
    if (!pair.active || pair.body != b) continue;
    for (const auto& c : pair.candidates) {
      const auto t = touch(pair, c, d);
      if (!(t.gap < 0)) continue;
      double B[3][3];
      particle_tangent(pair, c, t, B);
      for (std::size_t i = 0; i < udim; ++i)
        for (std::size_t j = 0; j < udim; ++j) local += a[i] * B[i][j] * a[j];
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, &local, &total);
  return total;
}

ImplicitContact::FirstTouch ImplicitContact::first_touch(const Vector& d_overlap, std::size_t b,
                                                         const double* a) const {
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<std::pair<double, const Candidate*>> gaps;
  std::vector<double> normal_along;
  double local = std::numeric_limits<double>::infinity(), nearest = local;
  for (const auto& pair : pairs_) {
    if (!pair.active || pair.body != b) continue;
    for (const auto& c : pair.candidates) {
      const auto t = touch(pair, c, d);
      gaps.emplace_back(t.gap, &c);
      double an = 0;
      for (int i = 0; i < dim_; ++i) an += a[i] * t.normal[i];
      normal_along.push_back(an);
      local = std::min(local, t.gap);
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, 1, &local, &nearest);
  // The candidates at the nearest gap (to a millionth of their size) touch first, together.
  double k_local = 0, k_total = 0;
  for (std::size_t i = 0; i < gaps.size(); ++i)
    if (gaps[i].first <= nearest + 1e-6 * gaps[i].second->size)
      k_local += gaps[i].second->stiffness * normal_along[i] * normal_along[i];
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, &k_local, &k_total);
  return {nearest, k_total};
}

}  // namespace efg
