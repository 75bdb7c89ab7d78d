// The CUDA render-pass kernel's launch interface: one kernel per integrator (templated on it,
// CudaRenderKernel.cuh), each instantiated in its own translation unit (CudaRender*.cu), so the
// path tracer's kernel does not carry the registers and stack of every other integrator and the
// build compiles them in parallel. Plain C++ header; CudaRenderer.cu calls launchRenderPass().
#pragma once

#include "accel/MajorantGrid.h"
#include "sampling/Media.h"
#include "render/RenderParams.h"

#include <cstdint>

namespace amrdm
{
namespace cuda
{

/// Work counters per pass: samples, steps, primitive tests, step-limit hits, violations.
constexpr int kNumPassCounters = 5;

/// Everything one pass needs on the device (pointers are device memory).
struct PassLaunch
{
  DualMeshMedium medium;
  MajorantGridView grid;
  RenderParams params; ///< resolved (resolveRenderParams)
  std::uint32_t frame = 0;
  const float* depthMaxT = nullptr;       ///< per pixel, or null
  const float* minT = nullptr;            ///< per pixel, or null
  double* sum = nullptr;                  ///< 4 per pixel
  double* sumSq = nullptr;                ///< 4 per pixel
  std::uint32_t* count = nullptr;         ///< 1 per pixel
  unsigned long long* counters = nullptr; ///< kNumPassCounters
};

/// Launches integrator I's kernel (asynchronously; the caller checks and synchronises).
template<IntegratorType I>
void launchRenderPassWith(const PassLaunch& launch);

/// Launches the kernel of launch.params.integrator.
void launchRenderPass(const PassLaunch& launch);

} // namespace cuda
} // namespace amrdm
