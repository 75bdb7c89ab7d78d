// One kernel source for the CPU and for CUDA: functions marked AMRDM_HD compile as
// __host__ __device__ under nvcc and as plain inline C++ everywhere else.
#pragma once

#if defined(__CUDACC__)
#define AMRDM_HD __host__ __device__ inline
#define AMRDM_DEVICE_CODE 1
#else
#define AMRDM_HD inline
#endif

/// Inlined into every host caller: the hot loops' small helpers, which GCC's size heuristics
/// otherwise leave as calls through the PLT (nvcc inlines device code on its own).
#if !defined(__CUDACC__) && (defined(__GNUC__) || defined(__clang__))
#define AMRDM_FORCE_INLINE __attribute__((always_inline))
#else
#define AMRDM_FORCE_INLINE
#endif

#define GLM_FORCE_XYZW_ONLY
#include <glm/glm.hpp>
