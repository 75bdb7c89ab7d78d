// CPU renderer: the RenderScene (render/RenderScene.h) drawn by tiles over threads
// (ParallelFor.h), progressive accumulation in double, cancellation between tiles. Passes run
// through TiledPass.h (samplePixel per pixel, PixelSamples.h), the same per-pixel code the CUDA
// kernel and the benchmark's loop run. Host code.
//
// Output: premultiplied RGBA, the mean over all samples of SampleResult (RGB = light scattered or
// emitted by the volume toward the camera; A = coverage: for the path tracer, single scattering
// and the primitive view the fraction of camera rays with a real collision, for the ray marcher
// the accumulated opacity). Composite over a background B as rgb + (1 - a) B.
#pragma once

#include "core/DefaultInitAllocator.h"
#include "render/PassCancellation.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

class CpuRenderer : public Renderer
{
public:
  RenderDevice device() const override { return RenderDevice::Cpu; }
  void setMesh(const DualMesh* mesh,
    glm::ivec3 majorantResolution = glm::ivec3(0),
    int threads = 0) override;
  void setTransferFunction(const TransferFunction& tf, int threads = 0) override;
  /// The proxy outside the region's box (Renderer.h, RenderScene::setProxy).
  void setProxy(const DualMesh* proxy,
    const glm::vec3& lo,
    const glm::vec3& hi,
    int threads = 0) override;
  void reset() override;
  /// Adds params.samplesPerPass samples to every pixel. Buffers are (re)sized to
  /// params.width x params.height (clearing them) when the size changed, and the scene's majorant
  /// grids rebuilt when params.majorantResolution changed. `depthMaxT` (optional, width*height
  /// floats, row-major from the bottom row) clips each camera ray at that distance along its unit
  /// direction (opaque geometry). `minT` (optional, same layout) starts each camera ray at that
  /// distance (clipping planes: a convex set of half-spaces leaves one interval [minT, maxT] per
  /// ray; minT >= maxT leaves the pixel empty). Returns false when cancel() stopped the pass:
  /// tiles already finished keep their samples (per-pixel counts stay exact).
  bool renderPass(const RenderParams& params,
    const float* depthMaxT = nullptr,
    const float* minT = nullptr) override;
  /// Asks the running pass to stop after the tiles in flight (thread safe); no effect when no
  /// pass runs (PassCancellation.h).
  void cancel() override { this->Cancellation.request(); }
  /// Tiles of params.tileSize pixels the running (or last) pass has finished.
  std::size_t tilesDone() const { return this->Cancellation.tilesDone(); }

  std::vector<float> image() const override;
  std::vector<float> varianceOfMean() const override;
  /// Samples accumulated in each pixel.
  const std::vector<std::uint32_t>& sampleCounts() const { return this->Count; }
  RenderStats stats() const override { return this->Totals.stats(this->Passes); }
  std::uint64_t accelerationBytes() const override { return this->Scene.accelerationBytes(); }
  /// The scene (majorant, composite and culling grids, transfer function) this renderer draws.
  const RenderScene& scene() const { return this->Scene; }
  const MajorantGrid& majorantGrid() const { return this->Scene.majorantGrid(); }
  const MajorantGrid& compositeMajorantGrid() const { return this->Scene.compositeMajorantGrid(); }
  const PrimitiveCulling& primitiveCulling() const { return this->Scene.primitiveCulling(); }
  const TransferFunction& transferFunction() const { return this->Scene.transferFunction(); }

private:
  RenderScene Scene;
  int Width = 0, Height = 0;
  /// Per-pixel sums in double: a float sum of 65536 samples keeps only ~8 of its 24 bits
  /// (TestRenderExtremes); 68 bytes per pixel with Count.
  std::vector<glm::dvec4, DefaultInitAllocator<glm::dvec4>> Sum, SumSq;
  std::vector<std::uint32_t> Count;
  PassCancellation Cancellation;
  int Passes = 0;
  PassTotals Totals;
};

} // namespace amrdm
