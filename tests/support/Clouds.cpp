#include "support/Clouds.hpp"

#include <random>

namespace efg::test {

ParticleCloud line_cloud(int n, double perturbation, const SectionSpec& section,
                         std::uint64_t seed) {
  ParticleCloud c;
  c.dimension = 1;
  c.section = section;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double h = 1.0 / n;
  for (int i = 0; i <= n; ++i) {
    double x = i * h;
    if (i > 0 && i < n) x += perturbation * h * u(rng);
    c.mesh_node.push_back(i);
    c.position.push_back(x);
    c.volume.push_back(i == 0 || i == n ? h / 2 : h);
  }
  // Spacing: the larger gap to a neighbour (as from the background cells around the node).
  for (int i = 0; i <= n; ++i) {
    const double left = i > 0 ? c.position[static_cast<std::size_t>(i)] -
                                    c.position[static_cast<std::size_t>(i - 1)]
                              : 0;
    const double right = i < n ? c.position[static_cast<std::size_t>(i + 1)] -
                                     c.position[static_cast<std::size_t>(i)]
                               : 0;
    c.support.push_back(section.dilation[0] * std::max(left, right));
  }
  c.owned_count = c.size();
  return c;
}

ParticleCloud mesh_cloud(const BackgroundMesh& mesh, const SectionSpec& section) {
  PartSpec part;
  part.name = "part";
  part.blocks = {mesh.blocks.front().name};
  part.section = section;
  return make_particle_cloud(mesh, part, std::vector<int>(mesh.node_count(), 0), 0, {});
}

std::vector<double> random_points(int dim, const std::array<double, 3>& lower,
                                  const std::array<double, 3>& upper, std::size_t count,
                                  std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> x;
  for (std::size_t p = 0; p < count; ++p)
    for (std::size_t d = 0; d < static_cast<std::size_t>(dim); ++d)
      x.push_back(std::uniform_real_distribution<double>(lower[d], upper[d])(rng));
  return x;
}

}  // namespace efg::test
