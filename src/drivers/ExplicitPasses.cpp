#include "drivers/ExplicitPasses.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <stdexcept>
#include <utility>

#include "core/DeviceArrays.hpp"
#include "parallel/ReproducibleSum.hpp"

namespace efg {
namespace {

using ConstView =
    decltype(std::declval<const Vector&>().getLocalViewDevice(Tpetra::Access::ReadOnly));

// Per block of reproducible_dot's block_size dofs: the N dots' partial sums, each added in index
// order (their chains independent of each other), and the count of non-finite d or v entries.
template <std::size_t N>
DeviceView<double**> block_sums(const std::vector<const Vector*>& forces, const ConstView& delta,
                                const ConstView& d, const ConstView& v) {
  Kokkos::Array<ConstView, N == 0 ? 1 : N> f;
  for (std::size_t i = 0; i < N; ++i)
    f[i] = forces[i]->getLocalViewDevice(Tpetra::Access::ReadOnly);
  const std::size_t n = delta.extent(0);
  const std::size_t blocks = (n + block_size - 1) / block_size;
  DeviceView<double**> partial(Kokkos::view_alloc(Kokkos::WithoutInitializing, "efg::step sums"),
                               blocks, N + 1);
  Kokkos::parallel_for(
      "efg::step_sums", Kokkos::RangePolicy<ExecSpace>(0, blocks),
      KOKKOS_LAMBDA(const std::size_t b) {
        double s[N == 0 ? 1 : N] = {};
        int bad = 0;
        const std::size_t end = (b + 1) * block_size < n ? (b + 1) * block_size : n;
        for (std::size_t k = b * block_size; k < end; ++k) {
          const double dk = delta(k, 0);
          for (std::size_t i = 0; i < N; ++i) s[i] += f[i](k, 0) * dk;
          bad |=
              !(Kokkos::Experimental::isfinite(d(k, 0)) && Kokkos::Experimental::isfinite(v(k, 0)));
        }
        for (std::size_t i = 0; i < N; ++i) partial(b, i) = s[i];
        partial(b, N) = bad;
      });
  return partial;
}

template <std::size_t... N>
DeviceView<double**> block_sums_of(std::index_sequence<N...>,
                                   const std::vector<const Vector*>& forces, const ConstView& delta,
                                   const ConstView& d, const ConstView& v) {
  DeviceView<double**> partial;
  // The one instantiation for forces.size() (0 .. max_forces).
  ((forces.size() == N ? (partial = block_sums<N>(forces, delta, d, v), 0) : 0), ...);
  return partial;
}

}  // namespace

void predict(double dt, const Vector& d_start, const Vector& v, const Vector& a, Vector& v_half,
             Vector& delta, Vector& d) {
  const auto d0 = d_start.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto v0 = v.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto a0 = a.getLocalViewDevice(Tpetra::Access::ReadOnly);
  auto vh = v_half.getLocalViewDevice(Tpetra::Access::OverwriteAll);
  auto dd = delta.getLocalViewDevice(Tpetra::Access::OverwriteAll);
  auto d1 = d.getLocalViewDevice(Tpetra::Access::OverwriteAll);
  const double half = 0.5 * dt;
  Kokkos::parallel_for(
      "efg::predict", Kokkos::RangePolicy<ExecSpace>(0, d1.extent(0)),
      KOKKOS_LAMBDA(const std::size_t k) {
        const double w = v0(k, 0) + half * a0(k, 0);
        const double step = dt * w;
        vh(k, 0) = w;
        dd(k, 0) = step;
        d1(k, 0) = d0(k, 0) + step;
      });
}

void predict_rows(const std::vector<int>& rows, double dt, const Vector& d_start,
                  const Vector& v_half, Vector& delta, Vector& d) {
  const auto d0 = d_start.getLocalViewHost(Tpetra::Access::ReadOnly);
  const auto vh = v_half.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto dd = delta.getLocalViewHost(Tpetra::Access::ReadWrite);
  auto d1 = d.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (const int row : rows) {
    const auto k = static_cast<std::size_t>(row);
    dd(k, 0) = dt * vh(k, 0);
    d1(k, 0) = d0(k, 0) + dd(k, 0);
  }
}

void acceleration_from_forces(const Vector& f_ext, const Vector& f_int, const Vector* f_wall,
                              const Vector* f_viscous, const Vector& inverse_mass, Vector& a,
                              const Vector* v_half, double half_dt, Vector* v_end) {
  const auto fe = f_ext.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto fi = f_int.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto im = inverse_mass.getLocalViewDevice(Tpetra::Access::ReadOnly);
  const bool wall = f_wall != nullptr, viscous = f_viscous != nullptr;
  const auto fw = (wall ? *f_wall : f_ext).getLocalViewDevice(Tpetra::Access::ReadOnly);
  const auto fv = (viscous ? *f_viscous : f_ext).getLocalViewDevice(Tpetra::Access::ReadOnly);
  auto out = a.getLocalViewDevice(Tpetra::Access::OverwriteAll);
  const bool corrector = v_end != nullptr && v_half != nullptr;
  const auto vh = (corrector ? *v_half : f_ext).getLocalViewDevice(Tpetra::Access::ReadOnly);
  // (an unused stand-in view when there is no corrector: the lambda needs one of its type)
  auto ve = corrector ? v_end->getLocalViewDevice(Tpetra::Access::OverwriteAll) : decltype(out)();
  Kokkos::parallel_for(
      "efg::acceleration", Kokkos::RangePolicy<ExecSpace>(0, out.extent(0)),
      KOKKOS_LAMBDA(const std::size_t k) {
        double t = fe(k, 0) - fi(k, 0);
        if (wall) t = t + fw(k, 0);
        if (viscous) t = t - fv(k, 0);
        const double acc = im(k, 0) * t;
        out(k, 0) = acc;
        if (corrector) ve(k, 0) = vh(k, 0) + half_dt * acc;
      });
}

StepSums step_sums(const std::vector<const Vector*>& forces, const Vector& delta, const Vector& d,
                   const Vector& v) {
  if (forces.size() > StepSums::max_forces)
    throw std::logic_error("step_sums: more than StepSums::max_forces forces");
  const auto device = block_sums_of(std::make_index_sequence<StepSums::max_forces + 1>{}, forces,
                                    delta.getLocalViewDevice(Tpetra::Access::ReadOnly),
                                    d.getLocalViewDevice(Tpetra::Access::ReadOnly),
                                    v.getLocalViewDevice(Tpetra::Access::ReadOnly));
  const auto partial = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), device);
  // Blocks in order on the host, then over ranks (block_sum, sum_over_ranks): one reduction for
  // the dots and the guard's count.
  const std::size_t n = forces.size();
  std::array<double, StepSums::max_forces + 1> mine{}, all{};
  for (std::size_t b = 0; b < partial.extent(0); ++b)
    for (std::size_t i = 0; i <= n; ++i) mine[i] += partial(b, i);
  Teuchos::reduceAll(*delta.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(n + 1),
                     mine.data(), all.data());
  StepSums sums;
  for (std::size_t i = 0; i < n; ++i) sums.work[i] = all[i];
  sums.finite = all[n] == 0;
  return sums;
}

}  // namespace efg
