// The thickness of a shell part at its particles (issue 18: "thickness per part, and per node
// where the mesh carries it"): the scene's parts[].shell.thickness, a number or an expression of
// the position, or, without it, the mesh's thickness attributes of the part's blocks (one value
// per cell, ElementBlock::thickness), each node taking the mean of its cells'. The integration
// points are the particles (scni, nodal), each with its own t_I; between them (edge points,
// probes) the thickness is interpolated by the shape functions, t(X) = sum phi_I(X) t_I
// (FlatShellOperator::thickness_at), which a linear or quadratic basis makes exact for a
// thickness linear in the position.
#pragma once

#include <vector>

#include "model/Model.hpp"

namespace efg {

/// t_I of every particle of part p's cloud (owned and ghost, cloud order). Throws InputError
/// naming the scene file and key when the part gives no thickness and a block of it carries
/// none, or a thickness is not a finite value > 0 at a particle.
std::vector<double> shell_particle_thickness(const Model& model, std::size_t part);

}  // namespace efg
