// Kokkos kernels of the solid operators over integration points: displacement gradient
// H = sum_I u_I (x) B_I, stress and tangent from the material (physics/), then
//   internal force  f_I,i        = sum_q w_q P_ij(q) B_qI,j
//   tangent         K_(I,i)(J,k) = sum_q w_q B_qI,j A_ijkl(q) B_qJ,l
//   strain energy   E            = sum_q w_q W(H_q)
// in two passes. Pass 1, one work item per point q, stores the force terms of its entries in
// particle order (force), or A(q) (tangent). Pass 2, one work item per particle I,
// *gathers* the contributions of the points that reach I (GatherIndex, ascending q) into I's
// force or I's matrix rows. Why a gather and not an atomic
// scatter: no two work items write the same particle, so the kernels are race-free on threads
// and GPUs without atomics (on a CPU an atomic add of a double is a compare-and-swap loop, paid
// for every entry), and every sum runs in one fixed order, so forces and matrices are bitwise
// identical on any number of threads (docs/threads.md). On Kokkos::Serial the force takes a
// one-pass scatter with the same bits (SerialForceKernel). The explicit and the implicit drivers
// call the same kernels.
#pragma once

#include <climits>

#include "core/DeviceArrays.hpp"
#include "discretization/GatherIndex.hpp"
#include "operators/PointMaterial.hpp"

namespace efg {

/// One part's integration points on the device. Entry k of point q's row couples the point to
/// overlap node node(k) with gradient grad(k, :); by_node lists every node's entries.
struct DevicePoints {
  DeviceView<const double*> weight;  ///< quadrature weight x thickness (2D)
  DeviceView<const std::size_t*> offsets;
  DeviceView<const int*> node;
  DeviceView<const double**> grad;
  GatherIndex by_node;
  DeviceView<const int*> slot;  ///< position of entry k in by_node order (by_node.entry inverted)
  PointMaterial material;
};

template <int Dim, class DisplacementView>
KOKKOS_INLINE_FUNCTION void displacement_gradient(const DevicePoints& p, const DisplacementView& u,
                                                  const int q, double (&H)[Dim][Dim]) {
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

/// Pass 1 of the tangent: A(q) = dP/dH into tangent(q, ((i * Dim + j) * Dim + k) * Dim + l).
/// `inverted` receives the smallest point index with det F <= 0 (INT_MAX when none); that
/// point's tangent is left unset (the caller reports it before the gather).
template <int Dim, class DisplacementView>
struct PointTangentKernel {
  DevicePoints p;
  DisplacementView u;
  DeviceView<double**> tangent;
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], P[Dim][Dim], A[Dim][Dim][Dim][Dim];
    displacement_gradient<Dim>(p, u, q, H);
    if (!point_stress<Dim>(p.material, q, H, P, A)) {
      Kokkos::atomic_fetch_min(&inverted(), q);
      return;
    }
    for (int m = 0; m < Dim * Dim * Dim * Dim; ++m) tangent(q, m) = (&A[0][0][0][0])[m];
  }
};

/// Component i of entry k's force term, w P_ij B_k,j: the one expression both force paths use,
/// so that they add the same numbers.
template <int Dim>
KOKKOS_INLINE_FUNCTION double force_term(const DevicePoints& p, const double (&P)[Dim][Dim],
                                         double w, std::size_t k, int i) {
  double fi = 0.0;
  for (int j = 0; j < Dim; ++j) fi += P[i][j] * p.grad(k, j);
  return w * fi;
}

/// Pass 1 of the force: per point q, the force terms w_q P(q) B_k of its entries, written to
/// their slots in particle order (each slot belongs to one entry: no two work items write the
/// same place). `inverted` as in PointTangentKernel; an inverted point writes zeros.
template <int Dim, class DisplacementView>
struct PointForceKernel {
  DevicePoints p;
  DisplacementView u;
  DeviceView<double**> term;  // entries x Dim, in by_node order
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], P[Dim][Dim];
    displacement_gradient<Dim>(p, u, q, H);
    const bool ok = point_stress<Dim>(p.material, q, H, P);
    if (!ok) Kokkos::atomic_fetch_min(&inverted(), q);
    const double w = p.weight(q);
    for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k) {
      const auto e = p.slot(k);
      for (int i = 0; i < Dim; ++i) term(e, i) = ok ? force_term<Dim>(p, P, w, k, i) : 0.0;
    }
  }
};

/// Pass 2 of the force: f(I) += the terms of I's slots, a contiguous stretch in ascending point
/// order.
template <int Dim, class ForceView>
struct NodalForceKernel {
  DevicePoints p;
  DeviceView<const double**> term;
  ForceView f;

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const {
    double fn[Dim];
    for (int i = 0; i < Dim; ++i) fn[i] = f(n * Dim + i);
    for (auto e = p.by_node.offsets(n); e < p.by_node.offsets(n + 1); ++e)
      for (int i = 0; i < Dim; ++i) fn[i] += term(e, i);
    for (int i = 0; i < Dim; ++i) f(n * Dim + i) = fn[i];
  }
};

/// The force in one pass for an execution space with one thread (Kokkos::Serial): per point,
/// stress then f(I) += w_q P(q) B_k for every entry. Each f(I) receives its terms in ascending q,
/// the order NodalForceKernel gathers them in, with the same arithmetic, so both give the same
/// bits; this one skips the stored terms and the second pass (measured on Debian's
/// Serial build, 105,300 particles: docs/threads.md). Never run on a space with threads.
template <int Dim, class DisplacementView, class ForceView>
struct SerialForceKernel {
  DevicePoints p;
  DisplacementView u;
  ForceView f;
  Kokkos::View<int, MemSpace> inverted;

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], P[Dim][Dim];
    displacement_gradient<Dim>(p, u, q, H);
    if (!point_stress<Dim>(p.material, q, H, P)) {
      Kokkos::atomic_fetch_min(&inverted(), q);
      return;
    }
    const double w = p.weight(q);
    for (std::size_t k = p.offsets(q); k < p.offsets(q + 1); ++k) {
      const int n = p.node(k);
      for (int i = 0; i < Dim; ++i) f(n * Dim + i) += force_term<Dim>(p, P, w, k, i);
    }
  }
};

/// Pass 2 of the tangent: the rows of particle I of a local (overlap) KokkosSparse matrix whose
/// column indices are overlap dof indices. Only this work item touches I's rows, so
/// sumIntoValues runs without atomics.
template <int Dim, class LocalMatrix>
struct NodalTangentKernel {
  DevicePoints p;
  DeviceView<const double**> tangent;
  LocalMatrix K;

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const {
    for (auto e = p.by_node.offsets(n); e < p.by_node.offsets(n + 1); ++e) {
      const auto a = p.by_node.entry(e);
      const int q = p.by_node.row_of_entry(a);
      const double w = p.weight(q);
      // G_ikl = sum_j B_a,j A_ijkl: the row block of particle I, reused for every column particle.
      double G[Dim][Dim][Dim];
      for (int i = 0; i < Dim; ++i)
        for (int k = 0; k < Dim; ++k)
          for (int l = 0; l < Dim; ++l) {
            double s = 0.0;
            for (int j = 0; j < Dim; ++j)
              s += p.grad(a, j) * tangent(q, ((i * Dim + j) * Dim + k) * Dim + l);
            G[i][k][l] = s;
          }
      // One sumIntoValues per row and chunk of 32 column particles: far fewer sorted-row
      // searches than one call per entry block, with a fixed-size scratch for any execution space.
      // The rows of the filled graph are sorted: a column the hint misses is found by binary
      // search, not by a scan of the whole row (3D rows hold 300-1,000 columns; the tangent of a
      // 40 x 8 x 8 block with SCNI subcells took 1.0-1.2 s that way, 0.30-0.39 s now).
      constexpr int chunk = 32;
      int cols[chunk * Dim];
      double vals[chunk * Dim];
      for (int i = 0; i < Dim; ++i)
        for (std::size_t first = p.offsets(q); first < p.offsets(q + 1); first += chunk) {
          const std::size_t last =
              first + chunk < p.offsets(q + 1) ? first + chunk : p.offsets(q + 1);
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
          K.sumIntoValues(n * Dim + i, cols, m, vals, true, false);
        }
    }
  }
};

/// Internal energy w_q W(H_q) of point q (point_energy: 0 when inverted), summed by the caller
/// in a thread-count-independent order (parallel/ReproducibleSum.hpp).
template <int Dim, class DisplacementView>
struct PointEnergy {
  DevicePoints p;
  DisplacementView u;

  KOKKOS_INLINE_FUNCTION double operator()(const std::size_t q) const {
    double H[Dim][Dim];
    displacement_gradient<Dim>(p, u, static_cast<int>(q), H);
    return p.weight(q) * point_energy<Dim>(p.material, static_cast<int>(q), H);
  }
};

/// Output of a path-dependent point q: the Cauchy stress (9 values, row major) at the committed
/// state, the effective plastic strain (column 9) and the erosion flag (column 10).
template <int Dim, class DisplacementView>
struct PointHistoryOutput {
  DevicePoints p;
  DisplacementView u;
  DeviceView<double**> out;  // points x 11

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], sigma[3][3];
    displacement_gradient<Dim>(p, u, q, H);
    point_cauchy_stress<Dim>(p.material, q, H, sigma);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out(q, i * 3 + j) = sigma[i][j];
    out(q, 9) = p.material.committed(q, physics::j2_state::alpha);
    out(q, 10) = p.material.committed(q, physics::j2_state::eroded);
  }
};

/// Energy w_q (stored + dissipated) of point q at the committed state if it has failed (eroded),
/// else 0: the energy erosion took out of the balance.
struct PointErodedEnergy {
  DevicePoints p;

  KOKKOS_INLINE_FUNCTION double operator()(const std::size_t q) const {
    const auto& s = p.material.committed;
    if (!(s(q, physics::j2_state::eroded) > 0.5)) return 0.0;
    return p.weight(q) *
           (s(q, physics::j2_state::elastic_energy) + s(q, physics::j2_state::dissipation));
  }
};

/// Kinematic measures of point q for the small-strain validity check: det(I + H) (<= 0 means
/// particles passed through each other) and the strain magnitude |sym H| (Frobenius norm).
template <int Dim, class DisplacementView>
struct PointKinematics {
  DevicePoints p;
  DisplacementView u;
  DeviceView<double**> out;  // points x 2

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double H[Dim][Dim], F[Dim][Dim], ee = 0;
    displacement_gradient<Dim>(p, u, q, H);
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) {
        F[i][j] = H[i][j] + (i == j ? 1.0 : 0.0);
        const double e = 0.5 * (H[i][j] + H[j][i]);
        ee += e * e;
      }
    // An eroded point is out of the model: its particles may pass through each other.
    const bool eroded =
        p.material.plastic && p.material.committed(q, physics::j2_state::eroded) > 0.5;
    out(q, 0) = eroded ? 1.0 : physics::determinant<Dim>(F);
    out(q, 1) = eroded ? 0.0 : sqrt(ee);
  }
};

}  // namespace efg
