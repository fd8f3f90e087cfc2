// A particle seen from the contact: its reference position X and its shape-function row (the
// overlap nodes I and values phi_I(X)). Shape functions do not interpolate, so its physical
// position is x = X + sum_I phi_I(X) d_I, and a force F on it reaches the generalized dofs as
// f_I += phi_I(X) F (work-consistent; sum_I phi_I = 1, so the particles receive exactly F).
// Both contact drivers (PenaltyContact, ImplicitContact) build their candidates on it.
#pragma once

#include <array>
#include <vector>

#include "operators/ModelOperators.hpp"

namespace efg {

struct ParticleRow {
  std::array<double, 3> X{};
  std::vector<int> nodes;  ///< overlap node indices
  std::vector<double> phi;

  /// x = X + sum phi_I d_I, d a host view of overlap dofs (dim per node).
  template <class View>
  std::array<double, 3> position(const View& d, std::size_t dim) const {
    std::array<double, 3> x = X;
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (std::size_t k = 0; k < dim; ++k)
        x[k] += phi[a] * d(static_cast<std::size_t>(nodes[a]) * dim + k, 0);
    return x;
  }
  /// f_I += phi_I F, f a host view of overlap dofs.
  template <class View>
  void spread(const double* F, std::size_t dim, const View& f) const {
    for (std::size_t a = 0; a < nodes.size(); ++a)
      for (std::size_t k = 0; k < dim; ++k)
        f(static_cast<std::size_t>(nodes[a]) * dim + k, 0) += phi[a] * F[k];
  }
};

/// The row of owned particle j of part p.
ParticleRow particle_row(const ModelOperators& ops, std::size_t p, std::size_t j);

/// The lumped mass of owned particle j of part p, `mass` a host view of the owned lumped masses
/// (one entry per owned dof, equal over a particle's components).
template <class View>
double particle_mass(const Model& model, const View& mass, std::size_t p, std::size_t j) {
  // the whole mesh's node index: on a part of a distributed read the mesh's own is local
  const auto node =
      model.mesh.global_node(static_cast<std::size_t>(model.parts[p].cloud.mesh_node[j]));
  const auto dof =
      static_cast<GlobalOrdinal>(node) * static_cast<GlobalOrdinal>(model.mesh.dimension);
  return mass(static_cast<std::size_t>(model.maps.owned_dofs->getLocalElement(dof)), 0);
}

/// 1 for the mesh nodes on the boundary of part p (the nodes of its boundary sides).
std::vector<char> surface_nodes(const Model& model, std::size_t p);

}  // namespace efg
