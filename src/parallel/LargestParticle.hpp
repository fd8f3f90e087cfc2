// Where a distributed per-dof quantity peaks by particle, named the same on every rank (for the
// messages of numerical trouble: the particle where an instability grows).
#pragma once

#include <Tpetra_Vector.hpp>

namespace efg {

struct ParticleValue {
  long long particle = -1;  ///< global particle id (dof / dim), -1 when there are no dofs
  double value = 0;
};

/// The particle whose dofs' entries of `w` sum to the largest value (ties: the lowest id), and
/// that sum; `dim` dofs per particle, numbered particle * dim + component. Collective.
ParticleValue largest_particle_sum(const Tpetra::Vector<>& w, int dim);

}  // namespace efg
