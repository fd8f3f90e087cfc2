// Particle clouds for discretization tests: every particle owned by this rank.
#pragma once

#include "discretization/ParticleCloud.hpp"
#include "mesh/MeshGenerator.hpp"

namespace efg::test {

/// A 1D cloud of n+1 particles on [0, 1] (perturbed by up to `perturbation` of the spacing).
ParticleCloud line_cloud(int n, double perturbation, const SectionSpec& section,
                         std::uint64_t seed = 5);

/// The cloud of a generated mesh's single block, all particles owned.
ParticleCloud mesh_cloud(const BackgroundMesh& mesh, const SectionSpec& section);

/// `count` points uniformly at random in the box [lower, upper] (dimension dim).
std::vector<double> random_points(int dim, const std::array<double, 3>& lower,
                                  const std::array<double, 3>& upper, std::size_t count,
                                  std::uint64_t seed);

}  // namespace efg::test
