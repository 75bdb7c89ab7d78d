// CUDA renderer: the CpuRenderer's interface on the GPU. One CUDA thread per pixel runs
// samplePixelWith<I>() (PixelSamples.h), the very code the CPU runs, in one kernel per integrator
// (CudaRenderKernel.h), with the same counter-based random streams; accumulation (sum, sum of
// squares, count) stays on the device between passes.
// Plain C++ header (no CUDA headers): only CudaRenderer.cu includes them. Exists only when the
// project was built with nvcc (AMRDM_HAVE_CUDA, target amrdm_cuda).
//
// Uploads: setMesh() uploads the dual mesh (gridlet headers and scalars, stitching vertices and
// indices, BVH nodes and primitive references) and derives the majorant ranges and culling
// ranges on the host; setTransferFunction() uploads only what the transfer function changes (its
// table, the majorants, the culling masks). Device allocations are RAII (CudaBuffers.h) and are
// reused when a re-upload keeps the size.
//
// Errors: every CUDA failure throws std::runtime_error naming the call; an allocation that does
// not fit throws GpuOutOfMemory naming the buffer, its size and the free memory.
#pragma once

#include "accel/MajorantGrid.h"
#include "accel/PrimitiveCulling.h"
#include "render/Renderer.h"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace amrdm
{

/// Thrown when a device allocation fails for lack of memory (RendererFactory.h's Auto device
/// then falls back to the CPU).
class GpuOutOfMemory : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// GPU memory by category, as in the paper supplement's Fig. 7: `computed` = our own count of
/// the bytes we asked for; `measured` = the drop of cudaMemGetInfo's free memory across that
/// category's allocations (allocation granularity and driver pools included; it can be 0 for a
/// small buffer placed in a page an earlier one reserved).
struct GpuMemoryReport
{
  struct Entry
  {
    std::string category;
    std::uint64_t computed = 0;
    std::int64_t measured = 0;
  };
  /// gridletScalars, gridletHeaders (plus the per-level width table, 4 B per level),
  /// elementVertices, elementIndices, bvh (nodes + primitive references), cullingMasks (1 B per
  /// BVH node and slot), majorantGrid (majorant and cell width, 8 B per macrocell),
  /// transferFunction (16 B per entry), frameBuffers (sum and sum of squares, 4 doubles = 32 B
  /// each, and a 4 B count per pixel), depthBuffers (4 B per pixel each, when given), counters (in
  /// that order). The first five equal DualMesh::memoryReport().
  std::vector<Entry> entries;
  std::string deviceName;
  std::uint64_t deviceTotal = 0; ///< cudaMemGetInfo total
  std::uint64_t deviceFree = 0;  ///< cudaMemGetInfo free now

  std::uint64_t computedTotal() const;
  std::int64_t measuredTotal() const;
  const Entry* find(const std::string& category) const;
  std::string toJson() const;
};

class CudaRenderer : public Renderer
{
public:
  /// Selects the current CUDA device (0) and creates its context. Throws std::runtime_error
  /// with the reason when no device can be used.
  CudaRenderer();
  ~CudaRenderer() override;
  CudaRenderer(const CudaRenderer&) = delete;
  CudaRenderer& operator=(const CudaRenderer&) = delete;

  RenderDevice device() const override { return RenderDevice::Cuda; }
  void setMesh(const DualMesh* mesh,
    glm::ivec3 majorantResolution = glm::ivec3(0),
    int threads = 0) override;
  void setTransferFunction(const TransferFunction& tf, int threads = 0) override;
  void reset() override;
  /// One kernel launch (one thread per pixel, params.samplesPerPass samples each), then a
  /// synchronisation, so errors surface here and timings are honest. A pass is one launch:
  /// cancel() during it makes it return false but keeps its samples (every pixel then has the
  /// same count). depthMaxT / minT are uploaded when given.
  bool renderPass(const RenderParams& params,
    const float* depthMaxT = nullptr,
    const float* minT = nullptr) override;
  void cancel() override;
  std::vector<float> image() const override;
  std::vector<float> varianceOfMean() const override;
  RenderStats stats() const override;
  /// memoryReport().toJson().
  std::string deviceMemoryJson() const override;

  /// Samples accumulated in each pixel (downloaded).
  std::vector<std::uint32_t> sampleCounts() const;
  /// Device memory by category: our count next to the measured drop in free memory.
  GpuMemoryReport memoryReport() const;
  /// Caps this renderer's device memory (our count, all categories): an allocation beyond it
  /// throws GpuOutOfMemory as a real shortage would. 0 (default) = no cap. For tests and for
  /// sharing a GPU.
  void setMemoryLimit(std::uint64_t bytes);
  /// The device's name, e.g. "NVIDIA H100 80GB HBM3".
  std::string deviceName() const;
  const MajorantGrid& majorantGrid() const;
  const PrimitiveCulling& primitiveCulling() const;
  /// The host copies of the majorant grid and the culling ranges and masks (Renderer.h).
  std::uint64_t accelerationBytes() const override
  {
    return this->majorantGrid().bytes() + this->primitiveCulling().bytes();
  }

private:
  struct Impl;
  std::unique_ptr<Impl> P;
};

} // namespace amrdm
