// One kernel source for the CPU and for CUDA: functions marked AMRDM_HD compile as
// __host__ __device__ under nvcc and as plain inline C++ everywhere else.
#pragma once

#if defined(__CUDACC__)
#define AMRDM_HD __host__ __device__ inline
#define AMRDM_DEVICE_CODE 1
#else
#define AMRDM_HD inline
#endif

#define GLM_FORCE_XYZW_ONLY
#include <glm/glm.hpp>
