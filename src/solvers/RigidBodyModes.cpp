#include "solvers/RigidBodyModes.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <array>
#include <stdexcept>

namespace efg {

int rigid_body_mode_count(int dimension) {
  return dimension == 1 ? 1 : (dimension == 2 ? 3 : 6);
}

namespace {

// The mesh's index of each owned particle.
std::vector<std::size_t> owned_mesh_nodes(const DofMaps& maps, const BackgroundMesh& mesh) {
  std::vector<std::size_t> nodes;
  for (auto gid : maps.owned_nodes->getNodeElementList()) {
    const auto n = mesh.node_of(static_cast<GlobalIndex>(gid));
    if (n < 0) throw std::logic_error("an owned particle is not in the rank's mesh");
    nodes.push_back(static_cast<std::size_t>(n));
  }
  return nodes;
}

// The centroid of the whole mesh's nodes.
std::array<double, 3> mesh_centre(const DofMaps& maps, const BackgroundMesh& mesh,
                                  const std::vector<std::size_t>& owned) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::array<double, 3> center = {0, 0, 0};
  if (!mesh.is_part()) {
    const std::size_t count = mesh.node_count();
    for (std::size_t n = 0; n < count; ++n)
      for (std::size_t c = 0; c < dim; ++c)
        center[c] += mesh.coordinates[n * dim + c] / static_cast<double>(count);
    return center;
  }
  std::array<double, 3> sum = {0, 0, 0};
  for (auto n : owned)
    for (std::size_t c = 0; c < dim; ++c) sum[c] += mesh.coordinates[n * dim + c];
  Teuchos::reduceAll(*maps.owned_nodes->getComm(), Teuchos::REDUCE_SUM, 3, sum.data(),
                     center.data());
  for (auto& c : center) c /= static_cast<double>(maps.owned_nodes->getGlobalNumElements());
  return center;
}

}  // namespace

Teuchos::RCP<Tpetra::MultiVector<>> rigid_body_modes(const DofMaps& maps,
                                                     const BackgroundMesh& mesh) {
  const int dimension = mesh.dimension;
  const auto& coordinates = mesh.coordinates;
  if (maps.dofs_per_node != dimension)
    throw std::logic_error("rigid_body_modes: one displacement dof per dimension expected");
  const auto modes = rigid_body_mode_count(dimension);
  auto z =
      Teuchos::rcp(new Tpetra::MultiVector<>(maps.owned_dofs, static_cast<std::size_t>(modes)));
  auto view = z->getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto nodes = owned_mesh_nodes(maps, mesh);
  const auto dim = static_cast<std::size_t>(dimension);
  const auto center = mesh_centre(maps, mesh, nodes);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto n = nodes[i];
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

Teuchos::RCP<Tpetra::MultiVector<>> particle_coordinates(const DofMaps& maps,
                                                         const BackgroundMesh& mesh) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  auto x = Teuchos::rcp(new Tpetra::MultiVector<>(maps.owned_nodes, dim));
  auto view = x->getLocalViewHost(Tpetra::Access::ReadWrite);
  const auto nodes = owned_mesh_nodes(maps, mesh);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t c = 0; c < dim; ++c) view(i, c) = mesh.coordinates[nodes[i] * dim + c];
  return x;
}

}  // namespace efg
