// Where efg's Kokkos kernels run and keep their arrays, and the copies between host vectors and
// those arrays. Kernels use ExecSpace (Kokkos' default execution space: Serial with Debian's
// Trilinos, OpenMP with scripts/build_trilinos_openmp.sh, CUDA elsewhere) and DeviceView; host
// code never dereferences a DeviceView except through these copies.
#pragma once

#include <Kokkos_Core.hpp>

#include <string>
#include <vector>

namespace efg {

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
template <class T>
using DeviceView = Kokkos::View<T, Kokkos::LayoutRight, MemSpace>;
template <class T>
using HostUnmanaged = Kokkos::View<T, Kokkos::LayoutRight, Kokkos::HostSpace,
                                   Kokkos::MemoryTraits<Kokkos::Unmanaged>>;

/// A device copy of a host vector.
template <class T>
DeviceView<T*> to_device(const std::vector<T>& host, const std::string& name) {
  DeviceView<T*> view(Kokkos::view_alloc(Kokkos::WithoutInitializing, name), host.size());
  Kokkos::deep_copy(view, HostUnmanaged<const T*>(host.data(), host.size()));
  return view;
}

/// A device copy of a row-major host matrix (rows x cols).
template <class T>
DeviceView<T**> to_device(const T* host, std::size_t rows, std::size_t cols,
                          const std::string& name) {
  DeviceView<T**> view(Kokkos::view_alloc(Kokkos::WithoutInitializing, name), rows, cols);
  Kokkos::deep_copy(view, HostUnmanaged<const T**>(host, rows, cols));
  return view;
}

/// The kernels' view of a host vector (1D) or row-major matrix (rows x cols, 2D) that outlives the
/// view: where the kernels read host memory (Serial, OpenMP) the host array itself, not a second
/// copy of it (issue 20: no duplicate host and device copies); elsewhere (CUDA) a device copy.
template <class T>
DeviceView<const T*> device_view_of(const std::vector<T>& host, const std::string& name) {
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible)
    return DeviceView<const T*>(host.data(), host.size());
  else
    return to_device(host, name);
}
template <class T>
DeviceView<const T**> device_view_of(const std::vector<T>& host, std::size_t rows, std::size_t cols,
                                     const std::string& name) {
  if constexpr (Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible)
    return DeviceView<const T**>(host.data(), rows, cols);
  else
    return to_device(host.data(), rows, cols, name);
}

/// The contents of a contiguous device view (any rank) as a host vector.
template <class View>
std::vector<typename View::non_const_value_type> to_host(const View& device) {
  using T = typename View::non_const_value_type;
  std::vector<T> host(device.size());
  Kokkos::deep_copy(HostUnmanaged<T*>(host.data(), host.size()),
                    Kokkos::View<const T*, Kokkos::LayoutRight, typename View::memory_space>(
                        device.data(), device.size()));
  return host;
}

}  // namespace efg
