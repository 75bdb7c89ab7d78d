// CPU renderer: tiles over threads (ParallelFor.h), progressive accumulation, cancellation.
// Owns the majorant grid and a copy of the transfer function; references the dual mesh.
// Host code; passes run through TiledPass.h (samplePixel per pixel, PixelSamples.h), the same
// per-pixel code the CUDA kernel and the benchmark's loop run.
//
// Output: premultiplied RGBA, the mean over all samples of SampleResult (RGB = light scattered or
// emitted by the volume toward the camera; A = coverage: for the path tracer, single scattering
// and the primitive view the fraction of camera rays with a real collision, for the ray marcher
// the accumulated opacity). Composite over a background B as rgb + (1 - a) B.
#pragma once

#include "core/DefaultInitAllocator.h"
#include "mesh/DualMesh.h"
#include "accel/MajorantGrid.h"
#include "accel/PrimitiveCulling.h"
#include "render/RenderParams.h"
#include "render/PassCancellation.h"
#include "render/Renderer.h"
#include "sampling/TransferFunction.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace amrdm
{

class CpuRenderer : public Renderer
{
public:
  RenderDevice device() const override { return RenderDevice::Cpu; }
  /// The mesh to render (not owned; must outlive the renderer's use). Rebuilds the majorant
  /// ranges (and majorants, if a transfer function is set). res <= 0: default resolution.
  void setMesh(const DualMesh* mesh,
    glm::ivec3 majorantResolution = glm::ivec3(0),
    int threads = 0) override;
  /// Copies the transfer function; recomputes majorants only (ranges are kept).
  void setTransferFunction(const TransferFunction& tf, int threads = 0) override;
  /// The proxy outside the region's box (Renderer.h). Its composite majorant grid
  /// (accel/CompositeMajorantGrid.h) spans the proxy's bounds at about the mesh's macrocell size.
  void setProxy(const DualMesh* proxy,
    const glm::vec3& lo,
    const glm::vec3& hi,
    int threads = 0) override;
  /// The composite grid (empty without a proxy).
  const MajorantGrid& compositeMajorantGrid() const { return this->Composite; }
  /// Clears the accumulation buffers and statistics.
  void reset() override;
  /// Adds params.samplesPerPass samples to every pixel. Buffers are (re)sized to
  /// params.width x params.height (clearing them) when the size changed, and the majorant ranges
  /// rebuilt when params.majorantResolution changed. `depthMaxT` (optional, width*height floats,
  /// row-major from the bottom row) clips each camera ray at that distance along its unit
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

  /// Mean premultiplied RGBA per pixel (4 floats each).
  std::vector<float> image() const override;
  /// Per-pixel variance of the mean, per channel (4 floats each): sample variance / count.
  std::vector<float> varianceOfMean() const override;
  /// Samples accumulated in each pixel.
  const std::vector<std::uint32_t>& sampleCounts() const { return this->Count; }
  RenderStats stats() const override;
  const MajorantGrid& majorantGrid() const { return this->Majorants; }
  std::uint64_t accelerationBytes() const override
  {
    return this->Majorants.bytes() + this->Culling.bytes() + this->Composite.bytes();
  }
  const PrimitiveCulling& primitiveCulling() const { return this->Culling; }
  const TransferFunction& transferFunction() const { return this->Tf; }

private:
  const DualMesh* Mesh = nullptr;
  TransferFunction Tf;
  bool HasTf = false;
  MajorantGrid Majorants;
  PrimitiveCulling Culling;        ///< value ranges per BVH slot/node; visibility from the TF
  const DualMesh* Proxy = nullptr; ///< DistributionMode Proxy: the whole domain, coarse
  glm::vec3 ProxyLo{ 0.0f }, ProxyHi{ 0.0f };
  MajorantGrid Composite; ///< the majorants of mesh-in-the-box + proxy-outside
  void updateComposite(int threads);
  glm::ivec3 RequestedResolution{ 0 };
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
