// Kokkos kernels of the solid operators over integration points: displacement gradient
// H = sum_I u_I (x) B_I, stress and tangent from the material (physics/), then
//   internal force  f_I,i      += w P_ij B_I,j
//   tangent         K_(I,i)(J,k) += w B_I,j A_ijkl B_J,l
//   strain energy   E          += w W(H)
// One work item per integration point. Several points add to the same particle, so forces and
// matrix entries are added atomically (race-free on threads and GPUs; a plain add on Serial).
// The explicit and the implicit drivers call the same InternalForceKernel.
#pragma once

#include <Kokkos_Core.hpp>

#include <climits>

#include "discretization/MlsKernel.hpp"
#include "materials/SolidMaterial.hpp"

namespace efg {

/// One part's integration points on the device. Entry k of point q's row couples the point to
/// overlap node node(k) with gradient grad(k, :).
struct DevicePoints {
  DeviceView<const double*> weight;  ///< quadrature weight x thickness (2D)
  DeviceView<const std::size_t*> offsets;
  DeviceView<const int*> node;
  DeviceView<const double**> grad;
  physics::SolidMaterial material;
};

template <int Dim, class DisplacementView>
KOKKOS_INLINE_FUNCTION void displacement_gradient(const DevicePoints& p, const DisplacementView& u, const int q,
                                                  double (&H)[Dim][Dim]) {
  for (int i = 0; i < Dim; ++i)
    for (int j = 0; j < Dim; ++j) H[i][j] = 0.0;
  for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k) {
    const int n = p.node(k);
    for (int i = 0; i < Dim; ++i) {
      const double ui = u(n * Dim + i);
      for (int j = 0; j < Dim; ++j) H[i][j] += ui * p.grad(k, j);
    }
  }
}

/// Stress P and tangent A at point q; false (and `inverted` lowered to q) when det F <= 0.
template <int Dim, class DisplacementView>
KOKKOS_INLINE_FUNCTION bool material_state(const DevicePoints& p, const DisplacementView& u, const int q,
                                           const Kokkos::View<int, MemSpace>& inverted, double (&P)[Dim][Dim],
                                           double (&A)[Dim][Dim][Dim][Dim]) {
  double H[Dim][Dim];
  displacement_gradient<Dim>(p, u, q, H);
  if (physics::stress_and_tangent<Dim>(p.material, H, P, A)) return true;
  Kokkos::atomic_fetch_min(&inverted(), q);
  return false;
}

/// f (overlap dofs) += internal force; `inverted` receives the smallest point index with
/// det F <= 0 (INT_MAX when none).
template <int Dim, class DisplacementView, class ForceView>
struct InternalForceKernel {
  DevicePoints p;
  DisplacementView u;
  ForceView f;
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double P[Dim][Dim], A[Dim][Dim][Dim][Dim];
    if (!material_state<Dim>(p, u, q, inverted, P, A)) return;
    const double w = p.weight(q);
    for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k) {
      const int n = p.node(k);
      for (int i = 0; i < Dim; ++i) {
        double fi = 0.0;
        for (int j = 0; j < Dim; ++j) fi += P[i][j] * p.grad(k, j);
        Kokkos::atomic_add(&f(n * Dim + i), w * fi);
      }
    }
  }
};

/// Adds the tangent of every point into a local (overlap) KokkosSparse matrix whose column
/// indices are overlap dof indices.
template <int Dim, class DisplacementView, class LocalMatrix>
struct TangentKernel {
  DevicePoints p;
  DisplacementView u;
  LocalMatrix K;
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double P[Dim][Dim], A[Dim][Dim][Dim][Dim];
    if (!material_state<Dim>(p, u, q, inverted, P, A)) return;
    const double w = p.weight(q);
    for (std::size_t a = p.offsets(q); a < p.offsets(q + 1); ++a) {
      // G_ikl = sum_j B_a,j A_ijkl: the row block of particle a, reused for every column particle.
      double G[Dim][Dim][Dim];
      for (int i = 0; i < Dim; ++i)
        for (int k = 0; k < Dim; ++k)
          for (int l = 0; l < Dim; ++l) {
            double s = 0.0;
            for (int j = 0; j < Dim; ++j) s += p.grad(a, j) * A[i][j][k][l];
            G[i][k][l] = s;
          }
      // One sumIntoValues per row and chunk of 32 column particles: far fewer sorted-row searches
      // than one call per entry block, with a fixed-size scratch that fits any execution space.
      constexpr int chunk = 32;
      int cols[chunk * Dim];
      double vals[chunk * Dim];
      const int row_node = p.node(a);
      for (int i = 0; i < Dim; ++i)
        for (std::size_t first = p.offsets(q); first < p.offsets(q + 1); first += chunk) {
          const std::size_t last = first + chunk < p.offsets(q + 1) ? first + chunk : p.offsets(q + 1);
          int m = 0;
          for (std::size_t b = first; b < last; ++b) {
            const int col_node = p.node(b);
            for (int k = 0; k < Dim; ++k, ++m) {
              double s = 0.0;
              for (int l = 0; l < Dim; ++l) s += G[i][k][l] * p.grad(b, l);
              cols[m] = col_node * Dim + k;
              vals[m] = w * s;
            }
          }
          K.sumIntoValues(row_node * Dim + i, cols, m, vals, false, true);
        }
    }
  }
};

/// Total strain energy of the points (inverted points count as +infinity).
template <int Dim, class DisplacementView>
struct EnergyKernel {
  DevicePoints p;
  DisplacementView u;

  KOKKOS_INLINE_FUNCTION void operator()(const int q, double& sum) const {
    double H[Dim][Dim];
    displacement_gradient<Dim>(p, u, q, H);
    sum += p.weight(q) * physics::strain_energy<Dim>(p.material, H);
  }
};

}  // namespace efg
