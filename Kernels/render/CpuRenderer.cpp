// CPU renderer: tiles over threads, progressive accumulation. See CpuRenderer.h.
#include "render/CpuRenderer.h"

#include "accel/CompositeMajorantGrid.h"
#include "sampling/CompositeMedium.h"

#include "mesh/DualMeshBuilder.h"
#include "core/ParallelFor.h"
#include "render/TiledPass.h"

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
  this->updateComposite(threads);
  this->reset();
}

void CpuRenderer::setProxy(const DualMesh* proxy,
  const glm::vec3& lo,
  const glm::vec3& hi,
  int threads)
{
  if (proxy && !glm::all(glm::lessThan(lo, hi)))
  {
    throw std::invalid_argument("CpuRenderer::setProxy: the region's box is empty; expected "
                                "lo < hi on every axis");
  }
  this->Proxy = proxy;
  this->ProxyLo = lo;
  this->ProxyHi = hi;
  this->updateComposite(threads);
  this->reset();
}

void CpuRenderer::updateComposite(int threads)
{
  this->Composite = MajorantGrid();
  if (!this->Proxy || !this->Mesh || this->Majorants.range.empty())
  {
    return;
  }
  glm::vec3 glo, ghi;
  this->Proxy->gridBounds(glo, ghi);
  const glm::vec3 w0(this->Proxy->origin + this->Proxy->finestSpacing * glm::dvec3(glo));
  const glm::vec3 w1(this->Proxy->origin + this->Proxy->finestSpacing * glm::dvec3(ghi));
  const MajorantGrid outer = buildMajorantRanges(*this->Proxy,
    compositeMajorantResolution(this->Majorants, glm::min(w0, w1), glm::max(w0, w1)),
    threads);
  this->Composite = compositeMajorantRanges(outer, this->Majorants, this->ProxyLo, this->ProxyHi);
  if (this->HasTf)
  {
    updateMajorants(this->Composite, this->Tf.view(), threads);
  }
}

void CpuRenderer::setTransferFunction(const TransferFunction& tf, int threads)
{
  this->Tf = tf;
  this->HasTf = true;
  updateMajorants(this->Majorants, this->Tf.view(), threads);
  updatePrimitiveVisibility(this->Culling, this->Tf.view(), threads);
  if (!this->Composite.range.empty())
  {
    updateMajorants(this->Composite, this->Tf.view(), threads);
  }
  this->reset();
}

void CpuRenderer::reset()
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
  this->Passes = 0;
  this->Totals.clear();
}

bool CpuRenderer::renderPass(const RenderParams& userParams,
  const float* depthMaxT,
  const float* minT)
{
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
  medium.countPrimitiveTests = integratorInfo(params.integrator).countsPrimitiveTests;
  const auto pass = [&](const auto& m, const MajorantGridView& grid)
  {
    runTiledPass(m,
      grid,
      params,
      static_cast<std::uint32_t>(this->Passes),
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
  };

  this->Cancellation.begin();
  // Scattered and shadow rays leave the region's box: with a proxy, the integrators that
  // scatter see it there. The others only follow camera rays, which are clipped to the box.
  if (!this->Composite.majorant.empty() && integratorInfo(params.integrator).scatters)
  {
    CompositeMedium composite;
    composite.inner = medium;
    composite.outer = medium;
    composite.outer.mesh = this->Proxy->view();
    composite.outer.origin = glm::vec3(this->Proxy->origin);
    composite.outer.invSpacing = 1.0f / glm::vec3(this->Proxy->finestSpacing);
    composite.lo = this->ProxyLo;
    composite.hi = this->ProxyHi;
    pass(composite, this->Composite.view());
  }
  else
  {
    pass(medium, this->Majorants.view());
  }
  ++this->Passes;
  return !this->Cancellation.end();
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
  return this->Totals.stats(this->Passes);
}

} // namespace amrdm
