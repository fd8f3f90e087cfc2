// Graded elastic materials: a Young's modulus written as an expression of x, y, z. The law keeps
// one reference modulus (the largest over the material's nodes: conservative for penalty
// factors and stable-step scales); each integration point carries the scale E(x_q) / E_ref that
// multiplies lambda and mu there (nu is fixed, so both scale with E).
#pragma once

#include <vector>

#include "mesh/BackgroundMesh.hpp"
#include "scene/Scene.hpp"

namespace efg {

/// Sets constants["youngs_modulus"] of every graded material to its largest value over the
/// nodes of the parts made of it (the mesh is replicated: every rank gets the same value).
void set_graded_references(Scene& scene, const BackgroundMesh& mesh);

/// E(x_q) / E_ref at `count` points (dimension coordinates each); empty for an ungraded material.
std::vector<double> modulus_scale(const MaterialSpec& material, const double* x, std::size_t count,
                                  int dimension);

}  // namespace efg
