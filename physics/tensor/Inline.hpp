// Physics kernels are plain functions of small fixed-size arrays, free of Trilinos. Where
// Kokkos is available they are also device functions, so the same code runs inside Kokkos
// kernels on any execution space.
#pragma once

#if __has_include(<Kokkos_Macros.hpp>)
#include <Kokkos_Macros.hpp>
#define EFG_PHYSICS_FUNCTION KOKKOS_INLINE_FUNCTION
#else
#define EFG_PHYSICS_FUNCTION inline
#endif
