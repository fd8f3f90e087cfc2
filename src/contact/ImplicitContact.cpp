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
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& spec : model.scene.contacts) {
    Pair pair;
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
        if (!(area[node] > 0)) continue;
        Candidate c;
        for (std::size_t k = 0; k < udim; ++k) c.X[k] = part.cloud.x(j)[k];
        c.stiffness = spec.implicit_penalty * E / size[node] * area[node];
        for (auto k = part.particle_values.offsets[j]; k < part.particle_values.offsets[j + 1];
             ++k) {
          c.nodes.push_back(ops.solid().overlap_node(
              p)[static_cast<std::size_t>(part.particle_values.particles[k])]);
          c.phi.push_back(part.particle_values.values[k]);
        }
        pair.candidates.push_back(std::move(c));
      }
    }
    pairs_.push_back(std::move(pair));
  }
}

void ImplicitContact::begin_stage(const std::vector<RigidBodyState>& carried, double t0) {
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
    for (const auto& c : pair.candidates) graph.add_clique(c.nodes.data(), c.nodes.size());
}

ImplicitContact::Touch ImplicitContact::touch(const Pair& p, const Candidate& c,
                                              const Vector& d_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  double x[3] = {c.X[0], c.X[1], c.X[2]};
  for (std::size_t a = 0; a < c.nodes.size(); ++a)
    for (std::size_t k = 0; k < udim; ++k)
      x[k] += c.phi[a] * d(static_cast<std::size_t>(c.nodes[a]) * udim + k, 0);
  const auto& shape = bodies_.shape(p.body);
  const double zero[3] = {0, 0, 0};
  const double* u_body = displacement_.empty() ? zero : displacement_[p.body].data();
  const auto near = contact::proximity(shape, x, u_body);
  Touch t;
  t.gap = near.gap;
  for (int i = 0; i < 3; ++i) t.normal[i] = near.normal[i];
  using Kind = contact::Shape::Kind;
  const bool round = shape.kind == Kind::sphere || (shape.kind == Kind::cylinder && dim_ == 2);
  if (round) {
    const double rho = shape.radius + near.gap;  // distance from the center
    if (rho > 0)
      for (int i = 0; i < dim_; ++i)
        for (int j = 0; j < dim_; ++j)
          t.dn[i][j] = ((i == j ? 1.0 : 0.0) - near.normal[i] * near.normal[j]) / rho;
  } else if (shape.kind == Kind::cylinder) {  // 3D: the axis direction does not turn n
    const double rho = shape.radius + near.gap;
    if (rho > 0)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          t.dn[i][j] = ((i == j ? 1.0 : 0.0) - near.normal[i] * near.normal[j] -
                        shape.axis[i] * shape.axis[j]) /
                       rho;
  }
  return t;
}

void ImplicitContact::add_residual(const Vector& d_overlap, Vector& r_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  auto r = r_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      const auto t = touch(pair, c, d_overlap);
      if (!(t.gap < 0)) continue;
      for (std::size_t a = 0; a < c.nodes.size(); ++a)
        for (std::size_t i = 0; i < udim; ++i)  // r -= phi F, F = k (-g) n
          r(static_cast<std::size_t>(c.nodes[a]) * udim + i, 0) +=
              c.phi[a] * c.stiffness * t.gap * t.normal[i];
    }
}

void ImplicitContact::add_tangent(const Vector& d_overlap, FEMatrix& K) const {
  const auto udim = static_cast<std::size_t>(dim_);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      const auto t = touch(pair, c, d_overlap);
      if (!(t.gap < 0)) continue;
      // d(k g n_i)/dx_j = k (n_i n_j + g dn_ij/dx_j); x_J = X_J + sum_K phi_K d_K.
      double B[3][3];
      for (std::size_t i = 0; i < udim; ++i)
        for (std::size_t j = 0; j < udim; ++j)
          B[i][j] = c.stiffness * (t.normal[i] * t.normal[j] + t.gap * t.dn[i][j]);
      const std::size_t n = c.nodes.size();
      std::vector<int> cols(n * udim);
      std::vector<double> vals(n * udim);
      for (std::size_t b = 0; b < n; ++b)
        for (std::size_t j = 0; j < udim; ++j)
          cols[b * udim + j] = c.nodes[b] * dim_ + static_cast<int>(j);
      for (std::size_t a = 0; a < n; ++a)
        for (std::size_t i = 0; i < udim; ++i) {
          for (std::size_t b = 0; b < n; ++b)
            for (std::size_t j = 0; j < udim; ++j)
              vals[b * udim + j] = c.phi[a] * c.phi[b] * B[i][j];
          K.sumIntoLocalValues(c.nodes[a] * dim_ + static_cast<int>(i),
                               static_cast<int>(cols.size()), vals.data(), cols.data());
        }
    }
}

std::vector<std::array<double, 3>> ImplicitContact::body_forces(const Vector& d_overlap) const {
  const std::size_t nb = bodies_.count();
  std::vector<double> local(3 * nb, 0.0), total(3 * nb, 0.0);
  for (const auto& pair : pairs_)
    for (const auto& c : pair.candidates) {
      const auto t = touch(pair, c, d_overlap);
      if (!(t.gap < 0)) continue;
      for (std::size_t i = 0; i < 3; ++i)
        local[3 * pair.body + i] += c.stiffness * t.gap * t.normal[i];
    }
  if (nb > 0)
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       total.data());
  std::vector<std::array<double, 3>> out(nb);
  for (std::size_t b = 0; b < nb; ++b) out[b] = {total[3 * b], total[3 * b + 1], total[3 * b + 2]};
  return out;
}

}  // namespace efg
