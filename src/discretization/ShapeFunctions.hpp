// MLS shape functions of a particle cloud at a batch of points: neighbour search on the host,
// evaluation by the Kokkos kernel MlsKernel, checks of every point's moment matrix.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "discretization/NeighborSearch.hpp"

namespace efg {

/// Values (and optionally gradients) of every neighbour's shape function at every point, in the
/// compressed rows of `neighbors`: phi[k] and grad[k * dim + d] for entry k.
struct ShapeFunctionValues {
  NeighborLists neighbors;
  std::vector<double> phi;
  std::vector<double> grad;         ///< empty without gradients
  std::vector<double> condition;    ///< per point: 1-norm condition number of the moment matrix
  std::size_t ill_conditioned = 0;  ///< points above condition_warning_threshold
};

/// A point's moment matrix with a 1-norm condition number above this draws a warning, above
/// condition_error_threshold an error. With the scaled, shifted basis well-posed node sets give
/// 1e1 to 1e4.
inline constexpr double condition_warning_threshold = 1e8;
inline constexpr double condition_error_threshold = 1e12;

/// Describes point p in messages ("SCNI face point 12 of cell 5"); default "evaluation point p".
using PointLabel = std::function<std::string(std::size_t)>;

/// Number of monomials of the basis: the fewest neighbours a point can have.
int basis_size(Basis basis, int dimension);

/// Throws NumericalError for the first point whose moment matrix is singular or worse than
/// condition_error_threshold, naming the point, its coordinates, its neighbour count, the
/// minimum needed and the dilation to raise.
ShapeFunctionValues evaluate_shape_functions(const ParticleCloud& cloud, const double* points,
                                             std::size_t count, bool gradients,
                                             const PointLabel& label = {});
/// The same with the cloud's search index built once by the caller (index_cloud(cloud)), for
/// many batches of points.
ShapeFunctionValues evaluate_shape_functions(const CloudIndex& index, const ParticleCloud& cloud,
                                             const double* points, std::size_t count,
                                             bool gradients, const PointLabel& label = {});

/// The rows `rows[k]` of `v`, in that order (a row may be taken more than once): the values at
/// points that coincide with evaluated ones.
ShapeFunctionValues select_rows(const ShapeFunctionValues& v, const std::vector<std::size_t>& rows,
                                int dim);

}  // namespace efg
