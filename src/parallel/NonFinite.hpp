// Where a distributed state stopped being finite, named the same on every rank (for the
// messages of numerical trouble: particle, step and time).
#pragma once

#include <Tpetra_Vector.hpp>

namespace efg {

/// A global dof id where `a` (or `b`, same map, when given) is not finite, the same on every rank
/// (each rank's first such dof, the largest over the ranks), or -1 when all are finite.
/// Collective.
long long non_finite_dof(const Tpetra::Vector<>& a, const Tpetra::Vector<>* b = nullptr);

}  // namespace efg
