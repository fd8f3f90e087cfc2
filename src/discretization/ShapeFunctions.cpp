#include "discretization/ShapeFunctions.hpp"

#include <cmath>
#include <sstream>

#include "core/Errors.hpp"
#include "discretization/MlsKernel.hpp"

namespace efg {
namespace {

template <int Dim, int Order>
void run_kernel(const CloudIndex& index, const ParticleCloud& cloud, const double* points,
                std::size_t count, bool gradients, ShapeFunctionValues& out,
                std::vector<int>& status) {
  MlsKernel<Dim, Order> k;
  k.points = to_device(points, count, Dim, "efg::mls points");
  k.particles = index.cloud.position;
  k.support = index.cloud.support;
  const auto lists = find_neighbors(index, k.points);
  k.offsets = lists.offsets;
  k.neighbors = lists.particles;
  const auto nnz = lists.particles.extent(0);
  DeviceView<double*> phi(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::mls phi"), nnz);
  DeviceView<double**> grad(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::mls grad"),
                            gradients ? nnz : 0, static_cast<std::size_t>(Dim));
  DeviceView<double*> condition(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::mls condition"), count);
  DeviceView<int*> point_status(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::mls status"),
                                count);
  k.phi = phi;
  k.grad = grad;
  k.condition = condition;
  k.status = point_status;
  k.kernel = static_cast<KernelShape>(static_cast<int>(cloud.section.kernel));
  k.sphere = cloud.section.support == SupportShape::sphere;
  k.with_gradients = gradients;
  Kokkos::parallel_for("efg::mls_shape_functions",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(count)), k);
  out.neighbors.offsets = to_host(lists.offsets);
  out.neighbors.particles = to_host(lists.particles);
  out.phi = to_host(phi);
  if (gradients) out.grad = to_host(grad);
  out.condition = to_host(condition);
  status = to_host(point_status);
}

template <int Dim>
void dispatch_order(const CloudIndex& index, const ParticleCloud& cloud, const double* points,
                    std::size_t count, bool gradients, ShapeFunctionValues& out,
                    std::vector<int>& status) {
  if (cloud.section.basis == Basis::linear)
    run_kernel<Dim, 1>(index, cloud, points, count, gradients, out, status);
  else
    run_kernel<Dim, 2>(index, cloud, points, count, gradients, out, status);
}

std::string describe_dilation(const SectionSpec& s) {
  std::ostringstream o;
  for (std::size_t i = 0; i < s.dilation.size(); ++i) o << (i ? ", " : "") << s.dilation[i];
  return o.str();
}

}  // namespace

int basis_size(Basis basis, int dimension) {
  return basis == Basis::linear ? 1 + dimension : 1 + dimension + dimension * (dimension + 1) / 2;
}

ShapeFunctionValues evaluate_shape_functions(const ParticleCloud& cloud, const double* points,
                                             std::size_t count, bool gradients,
                                             const PointLabel& label) {
  return evaluate_shape_functions(index_cloud(cloud), cloud, points, count, gradients, label);
}

ShapeFunctionValues evaluate_shape_functions(const CloudIndex& index, const ParticleCloud& cloud,
                                             const double* points, std::size_t count,
                                             bool gradients, const PointLabel& label) {
  ShapeFunctionValues out;
  std::vector<int> status;
  switch (cloud.dimension) {
    case 1:
      dispatch_order<1>(index, cloud, points, count, gradients, out, status);
      break;
    case 2:
      dispatch_order<2>(index, cloud, points, count, gradients, out, status);
      break;
    case 3:
      dispatch_order<3>(index, cloud, points, count, gradients, out, status);
      break;
    default:
      throw std::logic_error("shape functions: dimension must be 1, 2 or 3");
  }
  const auto dim = static_cast<std::size_t>(cloud.dimension);
  const int needed = basis_size(cloud.section.basis, cloud.dimension);
  for (std::size_t p = 0; p < count; ++p) {
    const bool finite = status[p] != mls_not_finite;
    const bool bad_condition =
        status[p] == mls_ok && !(out.condition[p] <= condition_error_threshold);
    if (status[p] == mls_ok && finite && !bad_condition) {
      if (out.condition[p] > condition_warning_threshold) ++out.ill_conditioned;
      continue;
    }
    std::ostringstream o;
    o << "shape functions: " << (label ? label(p) : "evaluation point " + std::to_string(p))
      << " at (";
    for (std::size_t d = 0; d < dim; ++d) o << (d ? ", " : "") << points[p * dim + d];
    o << "), at setup (step 0, time 0): ";
    const auto n = out.neighbors.count(p);
    if (status[p] == mls_too_few_neighbors) {
      o << "only " << n << " particle support(s) cover it, a "
        << (cloud.section.basis == Basis::linear ? "linear" : "quadratic") << " basis in " << dim
        << "D needs at least " << needed;
    } else if (status[p] == mls_singular || bad_condition) {
      o << "the moment matrix is "
        << (status[p] == mls_singular ? "singular" : "ill-conditioned (condition number ")
        << (status[p] == mls_singular ? "" : std::to_string(out.condition[p]) + ")") << " with "
        << n << " neighbours (at least " << needed << " needed, not all on one line or plane)";
    } else {
      o << "a shape function value is not finite";
    }
    o << "; increase the part's dilation (now " << describe_dilation(cloud.section) << ")";
    throw NumericalError(o.str());
  }
  return out;
}

ShapeFunctionValues select_rows(const ShapeFunctionValues& v, const std::vector<std::size_t>& rows,
                                int dim) {
  ShapeFunctionValues out;
  const auto d = static_cast<std::size_t>(dim);
  const bool gradients = !v.grad.empty();
  out.neighbors.offsets.assign(1, 0);
  for (const auto r : rows) {
    const auto from = v.neighbors.offsets[r], to = v.neighbors.offsets[r + 1];
    out.neighbors.particles.insert(
        out.neighbors.particles.end(),
        v.neighbors.particles.begin() + static_cast<std::ptrdiff_t>(from),
        v.neighbors.particles.begin() + static_cast<std::ptrdiff_t>(to));
    out.phi.insert(out.phi.end(), v.phi.begin() + static_cast<std::ptrdiff_t>(from),
                   v.phi.begin() + static_cast<std::ptrdiff_t>(to));
    if (gradients)
      out.grad.insert(out.grad.end(), v.grad.begin() + static_cast<std::ptrdiff_t>(from * d),
                      v.grad.begin() + static_cast<std::ptrdiff_t>(to * d));
    if (!v.condition.empty()) out.condition.push_back(v.condition[r]);
    out.neighbors.offsets.push_back(out.neighbors.particles.size());
  }
  out.ill_conditioned = v.ill_conditioned;
  return out;
}

}  // namespace efg
