// Small meshes and helpers shared by tests.
#pragma once

#include <string>

#include "mesh/MeshGenerator.hpp"

namespace efg::test {

/// A generated mesh of `element` on [0,2]x[0,1](x[0,1]) with `n` cells per unit length.
GeneratorSpec box_spec(CellType element, int n, double perturbation = 0.0, std::uint64_t seed = 3);

/// A fresh folder under the build tree for one test's files.
std::string scratch_dir(const std::string& name);

}  // namespace efg::test
