// Who evaluates the discrete fields at a point of space (probes, point displacements): the rank
// owning the particle nearest to it, which holds the point's whole support among its owned and
// ghost particles. Collective: every rank passes the same point.
#pragma once

#include "model/Model.hpp"

namespace efg {

/// The part of the nearest owned particle on the evaluating rank; -1 on every other rank. Ties
/// go to the lowest rank.
int evaluating_part(const Model& model, const double* point);

}  // namespace efg
