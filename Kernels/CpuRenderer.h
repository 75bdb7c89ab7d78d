// CPU renderer: tiles over threads (ParallelFor.h), progressive accumulation, cancellation.
// Owns the majorant grid and a copy of the transfer function; references the dual mesh.
// Host code; the per-sample work is Integrators.h, the same code a GPU launcher runs.
//
// Output: premultiplied RGBA, the mean over all samples of SampleResult (RGB = light scattered or
// emitted by the volume toward the camera; A = coverage: for the path tracer, single scattering
// and the primitive view the fraction of camera rays with a real collision, for the ray marcher
// the accumulated opacity). Composite over a background B as rgb + (1 - a) B.
#pragma once

#include "DualMesh.h"
#include "MajorantGrid.h"
#include "PrimitiveCulling.h"
#include "RenderParams.h"
#include "Renderer.h"
#include "TransferFunction.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace amrdm
{

class CpuRenderer : public Renderer
{
public:
  RenderDevice device() const override { return RenderDevice::Cpu; }
  /// The mesh to render (not owned; must outlive the renderer's use). Rebuilds the majorant
  /// ranges (and majorants, if a transfer function is set). res <= 0: default resolution.
  void setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution = glm::ivec3(0), int threads = 0) override;
  /// Copies the transfer function; recomputes majorants only (ranges are kept).
  void setTransferFunction(const TransferFunction& tf, int threads = 0) override;
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
  bool renderPass(const RenderParams& params, const float* depthMaxT = nullptr,
    const float* minT = nullptr) override;
  /// Asks the running pass to stop after the tiles in flight (thread safe).
  void cancel() override { this->CancelFlag.store(true); }

  /// Mean premultiplied RGBA per pixel (4 floats each).
  std::vector<float> image() const override;
  /// Per-pixel variance of the mean, per channel (4 floats each): sample variance / count.
  std::vector<float> varianceOfMean() const override;
  /// Samples accumulated in each pixel.
  const std::vector<std::uint32_t>& sampleCounts() const { return this->Count; }
  RenderStats stats() const override;
  const MajorantGrid& majorantGrid() const { return this->Majorants; }
  const PrimitiveCulling& primitiveCulling() const { return this->Culling; }
  const TransferFunction& transferFunction() const { return this->Tf; }

private:
  const DualMesh* Mesh = nullptr;
  TransferFunction Tf;
  bool HasTf = false;
  MajorantGrid Majorants;
  PrimitiveCulling Culling; ///< value ranges per BVH slot/node; visibility from the TF
  glm::ivec3 RequestedResolution{ 0 };
  int Width = 0, Height = 0;
  std::vector<glm::vec4> Sum, SumSq;
  std::vector<std::uint32_t> Count;
  std::atomic<bool> CancelFlag{ false };
  int Passes = 0;
  std::atomic<std::uint64_t> Samples{ 0 }, Steps{ 0 }, PrimitiveTests{ 0 }, StepLimitHits{ 0 },
    MajorantViolations{ 0 };
};

} // namespace amrdm
