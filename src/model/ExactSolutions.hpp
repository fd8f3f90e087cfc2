// Exact solutions a scene can verify against (verification.exact_solution) and take boundary
// data from (from_exact_solution). Each gives the displacement, the nominal (first
// Piola-Kirchhoff; Cauchy for small strain) stress for tractions P N, and the body force.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/Scene.hpp"

namespace efg {

struct ExactSolution {
  std::string name;
  std::function<void(const double* X, double* u)> displacement;
  std::function<void(const double* X, double (&P)[3][3])> nominal_stress;
  std::function<void(const double* X, double* b)> body_force;  ///< zero when empty
};

/// The scene's exact solution with its parameters (and the first part's material and plane
/// assumption). Throws InputError for unknown parameters or values out of range.
ExactSolution make_exact_solution(const Scene& scene, int dimension);

/// grad u of the exact displacement at x by central differences (step 1e-6 (1 + |x_0|); smooth
/// solutions): g[i][j] = du_i/dX_j for i, j < udim.
void exact_gradient(const ExactSolution& exact, const double* x, std::size_t udim,
                    double (&g)[3][3]);

/// The names make_exact_solution implements (equal to scene/ExactSolutionNames.hpp's list).
std::vector<std::string> implemented_exact_solutions();

}  // namespace efg
