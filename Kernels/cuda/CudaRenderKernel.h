// The CUDA render-pass kernel's launch interface: one kernel per integrator (templated on it,
// CudaRenderKernel.cuh), each instantiated in its own translation unit (CudaRender*.cu), so the
// path tracer's kernel does not carry the registers and stack of every other integrator and the
// build compiles them in parallel. Plain C++ header; CudaRenderer.cu calls launchRenderPass().
#pragma once

#include "accel/MajorantGrid.h"
#include "core/WorkCounters.h"
#include "render/RenderParams.h"
#include "sampling/CompositeMedium.h"

#include <cstdint>

namespace amrdm
{
namespace cuda
{

/// Work counters per pass: samples, then the work counters of core/WorkCounters.h in order.
constexpr int kNumPassCounters = 1 + kWorkCounterCount;

/// Everything one pass needs on the device (pointers are device memory).
struct PassLaunch
{
  /// medium.inner: the region's mesh, all a pass sees without `proxy`. With `proxy`
  /// (RenderScene::seesProxy: a proxy is set and the integrator scatters) the whole
  /// CompositeMedium: medium.outer is the proxy outside [medium.lo, medium.hi].
  CompositeMedium medium;
  bool proxy = false;
  MajorantGridView grid; ///< with `proxy`, the composite grid
  RenderParams params;   ///< resolved (resolveRenderParams)
  std::uint32_t frame = 0;
  const float* depthMaxT = nullptr;       ///< per pixel, or null
  const float* minT = nullptr;            ///< per pixel, or null
  double* sum = nullptr;                  ///< 4 per pixel
  double* sumSq = nullptr;                ///< 4 per pixel
  std::uint32_t* count = nullptr;         ///< 1 per pixel
  unsigned long long* counters = nullptr; ///< kNumPassCounters
};

/// Launches integrator I's kernel (asynchronously; the caller checks and synchronises), on the
/// composite medium when launch.proxy is set (integrators that scatter only: the others throw
/// std::logic_error, RenderScene::seesProxy never asks them to).
template<IntegratorType I>
void launchRenderPassWith(const PassLaunch& launch);

/// Launches the kernel of launch.params.integrator.
void launchRenderPass(const PassLaunch& launch);

} // namespace cuda
} // namespace amrdm
