#include "solvers/RigidBodyModes.hpp"

#include <stdexcept>

namespace efg {

int rigid_body_mode_count(int dimension) {
  return dimension == 1 ? 1 : (dimension == 2 ? 3 : 6);
}

Teuchos::RCP<Tpetra::MultiVector<>> rigid_body_modes(const DofMaps& maps, int dimension,
                                                     const std::vector<double>& coordinates) {
  if (maps.dofs_per_node != dimension)
    throw std::logic_error("rigid_body_modes: one displacement dof per dimension expected");
  const auto modes = rigid_body_mode_count(dimension);
  auto z =
      Teuchos::rcp(new Tpetra::MultiVector<>(maps.owned_dofs, static_cast<std::size_t>(modes)));
  auto view = z->getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto nodes = maps.owned_nodes->getNodeElementList();
  const auto dim = static_cast<std::size_t>(dimension);
  double center[3] = {0, 0, 0};
  const std::size_t count = coordinates.size() / dim;
  for (std::size_t n = 0; n < count; ++n)
    for (std::size_t c = 0; c < dim; ++c)
      center[c] += coordinates[n * dim + c] / static_cast<double>(count);
  for (std::size_t i = 0; i < static_cast<std::size_t>(nodes.size()); ++i) {
    const auto n = static_cast<std::size_t>(nodes[i]);
    double x[3] = {0, 0, 0};
    for (std::size_t c = 0; c < dim; ++c) x[c] = coordinates[n * dim + c] - center[c];
    const std::size_t row = i * dim;
    for (std::size_t c = 0; c < dim; ++c) view(row + c, c) = 1.0;  // translations
    if (dimension == 2) {                                          // rotation about z: (-y, x)
      view(row + 0, 2) = -x[1];
      view(row + 1, 2) = x[0];
    } else if (dimension == 3) {  // rotations about x (0,-z,y), y (z,0,-x), z (-y,x,0)
      view(row + 1, 3) = -x[2];
      view(row + 2, 3) = x[1];
      view(row + 0, 4) = x[2];
      view(row + 2, 4) = -x[0];
      view(row + 0, 5) = -x[1];
      view(row + 1, 5) = x[0];
    }
  }
  return z;
}

Teuchos::RCP<Tpetra::MultiVector<>> particle_coordinates(const DofMaps& maps, int dimension,
                                                         const std::vector<double>& coordinates) {
  const auto dim = static_cast<std::size_t>(dimension);
  auto x = Teuchos::rcp(new Tpetra::MultiVector<>(maps.owned_nodes, dim));
  auto view = x->getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto nodes = maps.owned_nodes->getNodeElementList();
  for (std::size_t i = 0; i < static_cast<std::size_t>(nodes.size()); ++i)
    for (std::size_t c = 0; c < dim; ++c)
      view(i, c) = coordinates[static_cast<std::size_t>(nodes[i]) * dim + c];
  return x;
}

}  // namespace efg
