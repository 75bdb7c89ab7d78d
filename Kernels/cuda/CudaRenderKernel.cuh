// The CUDA render-pass kernel, templated on the integrator (see CudaRenderKernel.h). Included
// only by the CudaRender*.cu files, each of which instantiates launchRenderPassWith<I> for its
// integrator(s).
#pragma once

#include "cuda/CudaRenderKernel.h"
#include "render/PixelSamples.h"

#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace amrdm
{
namespace cuda
{

constexpr unsigned kBlockX = 16, kBlockY = 8;

/// One thread per pixel: samplePixelWith<I>() (PixelSamples.h, the CPU's per-pixel code) on the
/// region's mesh or (Proxy) the composite medium, added to the pixel's double RGBA sum / sum of
/// squares and its count; work counters reduced per block in shared memory. __grid_constant__:
/// no per-thread copy of the launch arguments.
template<IntegratorType I, bool Proxy>
__global__ void __launch_bounds__(kBlockX* kBlockY)
  renderPassKernel(const __grid_constant__ PassLaunch a)
{
  __shared__ unsigned long long blockCounters[kNumPassCounters];
  const unsigned lane = threadIdx.y * blockDim.x + threadIdx.x;
  if (lane < kNumPassCounters)
  {
    blockCounters[lane] = 0;
  }
  __syncthreads();

  const int x = int(blockIdx.x * blockDim.x + threadIdx.x);
  const int y = int(blockIdx.y * blockDim.y + threadIdx.y);
  if (x < a.params.width && y < a.params.height)
  {
    const std::size_t pixel = std::size_t(y) * std::size_t(a.params.width) + std::size_t(x);
    const float maxT = a.depthMaxT ? a.depthMaxT[pixel] : kInfinity;
    const float startT = a.minT ? a.minT[pixel] : 0.0f;
    TraceCounters c;
    PixelSamples p;
    if constexpr (Proxy)
    {
      p = samplePixelWith<I>(a.medium, a.grid, a.params, x, y, a.frame, maxT, startT, c);
    }
    else
    {
      p = samplePixelWith<I>(a.medium.inner, a.grid, a.params, x, y, a.frame, maxT, startT, c);
    }
    for (int ch = 0; ch < 4; ++ch)
    {
      a.sum[4 * pixel + ch] += p.sum[ch];
      a.sumSq[4 * pixel + ch] += p.sumSq[ch];
    }
    a.count[pixel] += std::uint32_t(a.params.samplesPerPass);
    atomicAdd(&blockCounters[0], (unsigned long long)a.params.samplesPerPass);
    unsigned long long* next = &blockCounters[1]; // core/WorkCounters.h's order
#define AMRDM_BLOCK_COUNTER(name, doc)                                                             \
  if (c.name)                                                                                      \
    atomicAdd(next, (unsigned long long)c.name);                                                   \
  ++next;
    AMRDM_WORK_COUNTERS(AMRDM_BLOCK_COUNTER)
#undef AMRDM_BLOCK_COUNTER
  }
  __syncthreads();
  if (lane < kNumPassCounters && blockCounters[lane])
  {
    atomicAdd(&a.counters[lane], blockCounters[lane]);
  }
}

template<IntegratorType I>
void launchRenderPassWith(const PassLaunch& launch)
{
  const dim3 block(kBlockX, kBlockY);
  const dim3 blocks((unsigned(launch.params.width) + kBlockX - 1) / kBlockX,
    (unsigned(launch.params.height) + kBlockY - 1) / kBlockY);
  if (launch.proxy)
  {
    if constexpr (integratorInfo(I).scatters)
    {
      renderPassKernel<I, true><<<blocks, block>>>(launch);
      return;
    }
    throw std::logic_error(std::string("CUDA: integrator '") + integratorInfo(I).name +
                           "' does not scatter and has no proxy kernel; expected a launch "
                           "without the proxy (RenderScene::seesProxy)");
  }
  renderPassKernel<I, false><<<blocks, block>>>(launch);
}

} // namespace cuda
} // namespace amrdm
