// CUDA renderer: a thin backend over the host RenderScene (render/RenderScene.h), as the
// CpuRenderer is. One CUDA thread per pixel runs samplePixelWith<I>() (PixelSamples.h), the very
// code the CPU runs, in one kernel per integrator (CudaRenderKernel.h), with the same
// counter-based random streams; accumulation (sum, sum of squares, count) stays on the device
// between passes. It has not yet run on a GPU in this project (its tests skip without a device).
// The proxy medium (DistributionMode Proxy) is the scene's CompositeMedium, as on the CPU: the
// proxy mesh and the composite majorant grid are uploaded by setProxy(); that path compiles with
// nvcc but has never run (no GPU in this project's sessions so far).
// Plain C++ header (no CUDA headers): only CudaRenderer.cu includes them. Exists only when the
// project was built with nvcc (AMRDM_HAVE_CUDA, target amrdm_cuda).
//
// Uploads: setMesh() uploads the dual mesh (cuda::DeviceDualMesh) and the grids the scene derives
// from it; setTransferFunction() uploads only what the transfer function changes (its table, the
// majorants, the culling masks). Device allocations are RAII (CudaBuffers.h) and are
// reused when a re-upload keeps the size.
//
// Errors: every CUDA failure throws std::runtime_error naming the call; an allocation that does
// not fit throws GpuOutOfMemory naming the buffer, its size and the free memory.
#pragma once

#include "cuda/GpuMemoryReport.h"
#include "render/SceneRenderer.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace amrdm
{

/// The scene, its forwarding and the frame of a pass are SceneRenderer's. A pass is one kernel
/// launch (one thread per pixel, params.samplesPerPass samples each), then a synchronisation, so
/// errors surface there and timings are honest: cancel() during it makes renderPass return false
/// but keeps its samples (every pixel then has the same count). depthMaxT / minT are uploaded
/// when given.
class CudaRenderer : public SceneRenderer
{
public:
  /// Selects the current CUDA device (0) and creates its context. Throws std::runtime_error
  /// with the reason when no device can be used.
  CudaRenderer();
  ~CudaRenderer() override;
  CudaRenderer(const CudaRenderer&) = delete;
  CudaRenderer& operator=(const CudaRenderer&) = delete;

  RenderDevice device() const override { return RenderDevice::Cuda; }
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

private:
  /// Uploads what changed (the header's "Uploads").
  void sceneChanged(SceneChange what) override;
  void resizeAccumulation(int width, int height) override;
  void clearAccumulation() override;
  void runPass(const RenderParams& params, const float* depthMaxT, const float* minT) override;

  struct Impl;
  std::unique_ptr<Impl> P;
};

} // namespace amrdm
