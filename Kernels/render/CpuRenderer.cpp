// CPU renderer: tiles over threads, progressive accumulation. See CpuRenderer.h.
#include "render/CpuRenderer.h"

#include "core/ParallelFor.h"
#include "mesh/DualMeshBuilder.h" // For availableMemory()
#include "render/TiledPass.h"

#include <algorithm>

namespace amrdm
{

void CpuRenderer::clearAccumulation()
{
  // In parallel chunks: for freshly resized buffers this is the first touch of their pages.
  constexpr std::size_t kChunk = std::size_t(1) << 16;
  const std::size_t n = this->Sum.size();
  parallelFor((n + kChunk - 1) / kChunk,
    0,
    [&](std::size_t chunk)
    {
      const std::size_t b = chunk * kChunk, e = std::min(n, b + kChunk);
      std::fill(this->Sum.begin() + b, this->Sum.begin() + e, glm::dvec4(0.0));
      std::fill(this->SumSq.begin() + b, this->SumSq.begin() + e, glm::dvec4(0.0));
      std::fill(this->Count.begin() + b, this->Count.begin() + e, 0u);
    });
  this->Totals.clear();
}

void CpuRenderer::resizeAccumulation(int width, int height)
{
  // Free the old buffers first, then check the new ones fit (they would otherwise fail in the
  // middle of the allocation, or be killed by the OOM killer).
  decltype(this->Sum)().swap(this->Sum);
  decltype(this->SumSq)().swap(this->SumSq);
  std::vector<std::uint32_t>().swap(this->Count);
  checkAccumulationMemory(width, height, availableMemory());
  const std::size_t n = static_cast<std::size_t>(width) * height;
  this->Sum.resize(n); // uninitialised: clearAccumulation() zeroes them in parallel
  this->SumSq.resize(n);
  this->Count.resize(n);
}

void CpuRenderer::runPass(const RenderParams& params, const float* depthMaxT, const float* minT)
{
  this->scene().withMedium(params,
    [&](const auto& medium, const MajorantGridView& grid)
    {
      runTiledPass(medium,
        grid,
        params,
        static_cast<std::uint32_t>(this->passes()),
        depthMaxT,
        minT,
        &this->Cancellation,
        this->Totals,
        [&](std::size_t pixel, const PixelSamples& p)
        {
          this->Sum[pixel] += p.sum;
          this->SumSq[pixel] += p.sumSq;
          this->Count[pixel] += static_cast<std::uint32_t>(params.samplesPerPass);
        });
    });
}

std::vector<float> CpuRenderer::image() const
{
  return accumulatedImage(this->Sum.data(), nullptr, this->Count.data(), this->Sum.size());
}

std::vector<float> CpuRenderer::varianceOfMean() const
{
  return accumulatedImage(
    this->Sum.data(), this->SumSq.data(), this->Count.data(), this->Sum.size());
}

} // namespace amrdm
