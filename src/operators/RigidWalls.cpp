#include "operators/RigidWalls.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>

namespace efg {

RigidWalls::RigidWalls(const ModelOperators& ops, const Vector& mass_owned)
    : dim_(ops.model().mesh.dimension), comm_(ops.model().maps.owned_dofs->getComm()) {
  const auto& model = ops.model();
  const auto udim = static_cast<std::size_t>(dim_);
  const auto mass = mass_owned.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (const auto& spec : model.scene.rigid_walls) {
    Wall w;
    w.name = spec.name;
    w.penalty = spec.penalty;
    double norm = 0;
    for (std::size_t k = 0; k < udim; ++k) norm += spec.normal[k] * spec.normal[k];
    for (std::size_t k = 0; k < udim; ++k) {
      w.point[k] = spec.point[k];
      w.normal[k] = spec.normal[k] / std::sqrt(norm);
    }
    std::vector<char> in_set(model.mesh.node_count(), spec.node_set.empty() ? 1 : 0);
    if (!spec.node_set.empty())
      for (auto n : model.mesh.find_node_set(spec.node_set)->nodes)
        in_set[static_cast<std::size_t>(n)] = 1;
    for (std::size_t p = 0; p < model.parts.size(); ++p) {
      const auto& part = model.parts[p];
      for (std::size_t j = 0; j < part.cloud.owned_count; ++j) {
        const auto node = part.cloud.mesh_node[j];
        if (!in_set[static_cast<std::size_t>(node)]) continue;
        Contact c;
        for (std::size_t k = 0; k < udim; ++k) c.X[k] = part.cloud.x(j)[k];
        c.mass = mass(static_cast<std::size_t>(model.maps.owned_dofs->getLocalElement(
                          static_cast<GlobalOrdinal>(node) * dim_)),
                      0);
        for (auto k = part.particle_values.offsets[j]; k < part.particle_values.offsets[j + 1];
             ++k) {
          c.nodes.push_back(ops.solid().overlap_node(
              p)[static_cast<std::size_t>(part.particle_values.particles[k])]);
          c.phi.push_back(part.particle_values.values[k]);
        }
        w.particles.push_back(std::move(c));
      }
    }
    walls_.push_back(std::move(w));
  }
}

std::vector<double> RigidWalls::add_forces(const Vector& d_overlap, double dt,
                                           Vector& f_overlap) const {
  const auto udim = static_cast<std::size_t>(dim_);
  const auto d = d_overlap.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto f = f_overlap.getLocalViewHost(Tpetra::Access::ReadWrite);
  std::vector<double> local(walls_.size(), 0.0), total(walls_.size(), 0.0);
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const auto& wall = walls_[w];
    for (const auto& c : wall.particles) {
      double gap = 0;
      for (std::size_t k = 0; k < udim; ++k) {
        double u = 0;
        for (std::size_t a = 0; a < c.nodes.size(); ++a)
          u += c.phi[a] * d(static_cast<std::size_t>(c.nodes[a]) * udim + k, 0);
        gap += (c.X[k] + u - wall.point[k]) * wall.normal[k];
      }
      if (gap >= 0) continue;
      const double force = -wall.penalty * c.mass / (dt * dt) * gap;  // along the normal, > 0
      local[w] += force;
      for (std::size_t a = 0; a < c.nodes.size(); ++a)
        for (std::size_t k = 0; k < udim; ++k)
          f(static_cast<std::size_t>(c.nodes[a]) * udim + k, 0) +=
              c.phi[a] * force * wall.normal[k];
    }
  }
  if (!walls_.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, static_cast<int>(walls_.size()), local.data(),
                       total.data());
  return total;
}

}  // namespace efg
