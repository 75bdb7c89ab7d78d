// CPU renderer: tiles over threads, progressive accumulation. See CpuRenderer.h.
#include "CpuRenderer.h"

#include "DualMeshBuilder.h"
#include "Integrators.h"
#include "ParallelFor.h"

#include <algorithm>

namespace amrdm
{

void CpuRenderer::setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution, int threads)
{
  this->Mesh = mesh;
  this->RequestedResolution = majorantResolution;
  this->Majorants = mesh ? buildMajorantRanges(*mesh, majorantResolution, threads) : MajorantGrid();
  this->Culling = mesh ? buildPrimitiveRanges(*mesh, threads) : PrimitiveCulling();
  if (this->HasTf)
  {
    updateMajorants(this->Majorants, this->Tf.view(), threads);
    updatePrimitiveVisibility(this->Culling, this->Tf.view(), threads);
  }
  this->reset();
}

void CpuRenderer::setTransferFunction(const TransferFunction& tf, int threads)
{
  this->Tf = tf;
  this->HasTf = true;
  updateMajorants(this->Majorants, this->Tf.view(), threads);
  updatePrimitiveVisibility(this->Culling, this->Tf.view(), threads);
  this->reset();
}

void CpuRenderer::reset()
{
  // In parallel chunks: for freshly resized buffers this is the first touch of their pages.
  constexpr std::size_t kChunk = std::size_t(1) << 16;
  const std::size_t n = this->Sum.size();
  parallelFor((n + kChunk - 1) / kChunk, 0, [&](std::size_t chunk) {
    const std::size_t b = chunk * kChunk, e = std::min(n, b + kChunk);
    std::fill(this->Sum.begin() + b, this->Sum.begin() + e, glm::dvec4(0.0));
    std::fill(this->SumSq.begin() + b, this->SumSq.begin() + e, glm::dvec4(0.0));
    std::fill(this->Count.begin() + b, this->Count.begin() + e, 0u);
  });
  this->Passes = 0;
  this->Samples = 0;
  this->Steps = 0;
  this->PrimitiveTests = 0;
  this->StepLimitHits = 0;
  this->MajorantViolations = 0;
}

bool CpuRenderer::renderPass(
  const RenderParams& userParams, const float* depthMaxT, const float* minT)
{
  this->CancelFlag.store(false);
  if (!this->Mesh || !this->HasTf || userParams.width <= 0 || userParams.height <= 0)
  {
    return true;
  }
  if (userParams.width != this->Width || userParams.height != this->Height)
  {
    // Free the old buffers first, then check the new ones fit (they would otherwise fail in
    // the middle of the allocation, or be killed by the OOM killer).
    this->Width = this->Height = 0;
    decltype(this->Sum)().swap(this->Sum);
    decltype(this->SumSq)().swap(this->SumSq);
    std::vector<std::uint32_t>().swap(this->Count);
    checkAccumulationMemory(userParams.width, userParams.height, availableMemory());
    const std::size_t n = static_cast<std::size_t>(userParams.width) * userParams.height;
    this->Sum.resize(n); // uninitialised: reset() zeroes them in parallel
    this->SumSq.resize(n);
    this->Count.resize(n);
    this->Width = userParams.width;
    this->Height = userParams.height;
    this->reset();
  }
  if (userParams.majorantResolution != this->RequestedResolution)
  {
    this->setMesh(this->Mesh, userParams.majorantResolution, userParams.threads);
  }

  // Resolve the "0 = automatic" parameters from the mesh.
  const RenderParams params = resolveRenderParams(userParams, *this->Mesh);
  const glm::vec3 spacing(this->Mesh->finestSpacing);
  const int tile = std::clamp(params.tileSize, 4, 256);

  DualMeshMedium medium;
  medium.mesh = this->Mesh->view();
  if (cullingEnabled(params))
  {
    medium.mesh.bvh = this->Culling.apply(medium.mesh.bvh);
  }
  medium.tf = this->Tf.view();
  medium.elementTest = params.elementTest;
  medium.origin = glm::vec3(this->Mesh->origin);
  medium.invSpacing = 1.0f / spacing;
  medium.countPrimitiveTests = params.integrator == IntegratorType::DebugCost;
  const MajorantGridView grid = this->Majorants.view();

  const int tilesX = (this->Width + tile - 1) / tile;
  const int tilesY = (this->Height + tile - 1) / tile;
  const std::uint32_t frame = static_cast<std::uint32_t>(this->Passes);
  parallelFor(static_cast<std::size_t>(tilesX) * tilesY, params.threads, [&](std::size_t tileIndex) {
    if (this->CancelFlag.load(std::memory_order_relaxed))
    {
      return;
    }
    const int x0 = static_cast<int>(tileIndex % tilesX) * tile;
    const int y0 = static_cast<int>(tileIndex / tilesX) * tile;
    const int x1 = std::min(x0 + tile, this->Width), y1 = std::min(y0 + tile, this->Height);
    TraceCounters counters;
    std::uint64_t samples = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x)
      {
        const std::size_t pixel = static_cast<std::size_t>(y) * this->Width + x;
        const float maxT = depthMaxT ? depthMaxT[pixel] : kInfinity;
        const float startT = minT ? minT[pixel] : 0.0f;
        glm::dvec4 sum(0.0), sumSq(0.0);
        for (int s = 0; s < params.samplesPerPass; ++s)
        {
          const SampleResult r = renderSample(medium, grid, params, x, y,
            static_cast<std::uint32_t>(s), frame, maxT, counters, startT);
          const glm::dvec4 v(glm::vec4(r.L, r.alpha));
          sum += v;
          sumSq += v * v;
        }
        this->Sum[pixel] += sum;
        this->SumSq[pixel] += sumSq;
        this->Count[pixel] += static_cast<std::uint32_t>(params.samplesPerPass);
        samples += static_cast<std::uint64_t>(params.samplesPerPass);
      }
    this->Samples += samples;
    this->Steps += counters.steps;
    this->PrimitiveTests += counters.primitiveTests;
    this->StepLimitHits += counters.stepLimitHits;
    this->MajorantViolations += counters.majorantViolations;
  });
  ++this->Passes;
  return !this->CancelFlag.load();
}

std::vector<float> CpuRenderer::image() const
{
  std::vector<float> out(this->Sum.size() * 4, 0.0f);
  for (std::size_t i = 0; i < this->Sum.size(); ++i)
  {
    const glm::vec4 m = accumulatedMean(this->Sum[i], this->Count[i]);
    for (int c = 0; c < 4; ++c)
      out[4 * i + c] = m[c];
  }
  return out;
}

std::vector<float> CpuRenderer::varianceOfMean() const
{
  std::vector<float> out(this->Sum.size() * 4, 0.0f);
  for (std::size_t i = 0; i < this->Sum.size(); ++i)
  {
    const glm::vec4 v = accumulatedVarianceOfMean(this->Sum[i], this->SumSq[i], this->Count[i]);
    for (int c = 0; c < 4; ++c)
      out[4 * i + c] = v[c];
  }
  return out;
}

RenderStats CpuRenderer::stats() const
{
  RenderStats s;
  s.samples = this->Samples.load();
  s.steps = this->Steps.load();
  s.primitiveTests = this->PrimitiveTests.load();
  s.stepLimitHits = this->StepLimitHits.load();
  s.majorantViolations = this->MajorantViolations.load();
  s.passes = this->Passes;
  return s;
}

} // namespace amrdm
