// CPU renderer: the RenderScene (render/RenderScene.h) drawn by tiles over threads
// (ParallelFor.h), progressive accumulation in double, cancellation between tiles. Passes run
// through TiledPass.h (samplePixelWith<I> per pixel, PixelSamples.h), the same per-pixel code the
// CUDA kernel and the benchmark's loop run. Host code.
//
// Output: premultiplied RGBA, the mean over all samples of SampleResult (RGB = light scattered or
// emitted by the volume toward the camera; A = coverage: for the path tracer, single scattering
// and the primitive view the fraction of camera rays with a real collision, for the ray marcher
// the accumulated opacity). Composite over a background B as rgb + (1 - a) B.
#pragma once

#include "core/DefaultInitAllocator.h"
#include "render/SceneRenderer.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

/// The scene, its forwarding and the frame of a pass are SceneRenderer's; renderPass: buffers are
/// (re)sized to params.width x params.height (clearing them) when the size changed. `depthMaxT`
/// (optional, width*height floats, row-major from the bottom row) clips each camera ray at that
/// distance along its unit direction (opaque geometry). `minT` (optional, same layout) starts each
/// camera ray at that distance (clipping planes: a convex set of half-spaces leaves one interval
/// [minT, maxT] per ray; minT >= maxT leaves the pixel empty). cancel() stops the pass after the
/// tiles in flight: tiles already finished keep their samples (per-pixel counts stay exact).
class CpuRenderer : public SceneRenderer
{
public:
  RenderDevice device() const override { return RenderDevice::Cpu; }
  /// Tiles of params.tileSize pixels the running (or last) pass has finished.
  std::size_t tilesDone() const { return this->Cancellation.tilesDone(); }
  std::vector<float> image() const override;
  std::vector<float> varianceOfMean() const override;
  /// Samples accumulated in each pixel.
  const std::vector<std::uint32_t>& sampleCounts() const { return this->Count; }
  RenderStats stats() const override { return this->Totals.stats(this->passes()); }

private:
  void resizeAccumulation(int width, int height) override;
  void clearAccumulation() override;
  void runPass(const RenderParams& params, const float* depthMaxT, const float* minT) override;

  /// Per-pixel sums in double: a float sum of 65536 samples keeps only ~8 of its 24 bits
  /// (TestRenderExtremes); 68 bytes per pixel with Count.
  std::vector<glm::dvec4, DefaultInitAllocator<glm::dvec4>> Sum, SumSq;
  std::vector<std::uint32_t> Count;
  PassTotals Totals;
};

} // namespace amrdm
