#include "contact/ImplicitContact.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>

#include "discretization/SmoothingFacets.hpp"
#include "mesh/SideMeasures.hpp"

namespace efg {

ImplicitContact::ImplicitContact(const ModelOperators& ops)
    : dim_(ops.model().mesh.dimension),
      bodies_(ops.model().scene, ops.model().mesh.dimension),
      comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto& mesh = model.mesh;
  for (const auto& spec : model.scene.contacts) {
    if (spec.rigid_body.empty()) continue;  // between deformable parts: refused by the scene
    Pair pair;
    pair.spec = &spec;
    for (std::size_t b = 0; b < bodies_.count(); ++b)
      if (bodies_.name(b) == spec.rigid_body) pair.body = b;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      if (std::find(spec.parts.begin(), spec.parts.end(), part.part->name) == spec.parts.end())
        continue;
      const double thickness = dim_ == 2 ? part.part->thickness : 1.0;
      const double E =
          model.scene.find_material(part.part->material)->constants.at("youngs_modulus");
      std::vector<double> area(mesh.node_count(), 0.0), size(mesh.node_count(), 0.0);
      for (const auto& [cell, side] : boundary_sides(mesh, part.part->blocks)) {
        const auto nodes = mesh.side_node_indices(cell, side);
        const double share =
            side_measure(mesh, nodes) * thickness / static_cast<double>(nodes.size());
        const double h = side_longest_edge(mesh, nodes);
        for (auto n : nodes) {
          area[static_cast<std::size_t>(n)] += share;
          size[static_cast<std::size_t>(n)] = std::max(size[static_cast<std::size_t>(n)], h);
        }
      }
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
        const auto node = static_cast<std::size_t>(part.cloud.mesh_node[j]);
        if (!(area[node] > 0)) continue;  // not on the part's surface
        pair.candidates.push_back(
            {particle_row(ops, p, j), spec.implicit_penalty * E / size[node] * area[node]});
      }
    }
    pairs_.push_back(std::move(pair));
  }
}

void ImplicitContact::begin_stage(const std::vector<RigidBodyState>& carried, double t0,
                                  const std::string& stage) {
  for (auto& pair : pairs_) pair.active = pair.spec->stages.includes(stage);
  t0_ = t0;
  start_.assign(bodies_.count(), {0.0, 0.0, 0.0});
  for (std::size_t b = 0; b < std::min(carried.size(), start_.size()); ++b)
    start_[b] = carried[b].displacement;
  displacement_ = start_;
}

void ImplicitContact::set_time(double t) {
  if (start_.size() != bodies_.count()) begin_stage({}, t0_);
  for (std::size_t b = 0; b < bodies_.count(); ++b) {
    const auto travel = bodies_.prescribed_travel(b, t0_, t);
    for (std::size_t k = 0; k < 3; ++k) displacement_[b][k] = start_[b][k] + travel[k];
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
  const auto near = contact::proximity(shape, x.data(), u_body);
  Touch t;
  t.gap = near.gap;
  for (int i = 0; i < 3; ++i) t.normal[i] = near.normal[i];
  contact::normal_derivative(shape, near, t.dn);
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
      double minus_F[3];  // r -= phi F, F = k (-g) n
      for (std::size_t i = 0; i < 3; ++i) minus_F[i] = c.stiffness * t.gap * t.normal[i];
      c.row.spread(minus_F, udim, r);
    }
}

void ImplicitContact::add_tangent(const Vector& d_overlap, FEMatrix& K) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      if (!pair.active) break;  // the whole pair is out of this stage
      const auto t = touch(pair, c, d);
      if (!(t.gap < 0)) continue;
      // d(k g n_i)/dx_j = k (n_i n_j + g dn_ij/dx_j); x_J = X_J + sum_K phi_K d_K.
      double B[3][3];
      for (std::size_t i = 0; i < udim; ++i)
        for (std::size_t j = 0; j < udim; ++j)
          B[i][j] = c.stiffness * (t.normal[i] * t.normal[j] + t.gap * t.dn[i][j]);
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
        F[i] = c.stiffness * t.gap * t.normal[i];
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

}  // namespace efg
