// Device choice: which Renderer implementation to create. Header-only so that it sees whether the
// including target links amrdm_cuda (which defines AMRDM_HAVE_CUDA publicly); a CPU-only build
// needs no CUDA at all.
//   Cpu:  CpuRenderer.
//   Cuda: CudaRenderer; std::runtime_error naming the reason when this build has no CUDA or no
//         device can be used. Out of device memory is GpuOutOfMemory (an error, no fallback).
//   Auto: CUDA when a device can be used, else the CPU, said once through `log`. Out of device
//         memory (mesh upload, transfer function, frame buffers) switches to the CPU, said once,
//         and the interrupted call is replayed there (accumulated samples restart).
// Host code.
#pragma once

#include "CpuRenderer.h"

#if defined(AMRDM_HAVE_CUDA) && AMRDM_HAVE_CUDA
#include "CudaLauncher.h"
#include "CudaRenderer.h"
#define AMRDM_RENDERER_FACTORY_CUDA 1
#endif

#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace amrdm
{

/// Receives the factory's one-line messages (device chosen, fallback).
using RendererLog = std::function<void(const std::string&)>;

/// True when this build has CUDA and a device can be used; otherwise `reason` says why.
inline bool cudaRenderingAvailable(std::string* reason = nullptr)
{
#ifdef AMRDM_RENDERER_FACTORY_CUDA
  return cuda::deviceAvailable(reason);
#else
  if (reason)
  {
    *reason = "this build has no CUDA support (nvcc was not found or AMRDM_ENABLE_CUDA=OFF)";
  }
  return false;
#endif
}

#ifdef AMRDM_RENDERER_FACTORY_CUDA
/// Auto device with CUDA: a CudaRenderer that hands over to a CpuRenderer when the device runs
/// out of memory, replaying the mesh and transfer function.
class FallbackRenderer : public Renderer
{
public:
  FallbackRenderer(std::unique_ptr<Renderer> gpu, RendererLog log)
    : Active(std::move(gpu))
    , Log(std::move(log))
  {
  }
  RenderDevice device() const override { return this->Active->device(); }
  void setMesh(const DualMesh* mesh, glm::ivec3 res, int threads) override
  {
    this->Mesh = mesh;
    this->Resolution = res;
    this->Threads = threads;
    this->guarded([&] { this->Active->setMesh(mesh, res, threads); });
  }
  void setTransferFunction(const TransferFunction& tf, int threads) override
  {
    this->Tf = tf;
    this->HasTf = true;
    this->guarded([&] { this->Active->setTransferFunction(tf, threads); });
  }
  void reset() override { this->Active->reset(); }
  bool renderPass(const RenderParams& params, const float* depthMaxT, const float* minT) override
  {
    bool result = true;
    this->guarded([&] { result = this->Active->renderPass(params, depthMaxT, minT); });
    return result;
  }
  void cancel() override { this->Active->cancel(); }
  std::vector<float> image() const override { return this->Active->image(); }
  std::vector<float> varianceOfMean() const override { return this->Active->varianceOfMean(); }
  RenderStats stats() const override { return this->Active->stats(); }
  std::string deviceMemoryJson() const override { return this->Active->deviceMemoryJson(); }

private:
  template <typename F>
  void guarded(F&& f)
  {
    try
    {
      f();
    }
    catch (const GpuOutOfMemory& e)
    {
      if (this->Active->device() != RenderDevice::Cuda)
      {
        throw;
      }
      if (this->Log)
      {
        this->Log(std::string(e.what()) + "; falling back to the CPU renderer");
      }
      this->Active.reset(); // frees the device memory first
      this->Active.reset(new CpuRenderer);
      if (this->Mesh)
      {
        this->Active->setMesh(this->Mesh, this->Resolution, this->Threads);
      }
      if (this->HasTf)
      {
        this->Active->setTransferFunction(this->Tf, this->Threads);
      }
      f();
    }
  }

  std::unique_ptr<Renderer> Active;
  RendererLog Log;
  const DualMesh* Mesh = nullptr;
  glm::ivec3 Resolution{ 0 };
  int Threads = 0;
  TransferFunction Tf;
  bool HasTf = false;
};
#endif

/// Creates the renderer for `device` (see the top of this file). `log` (default: stderr) gets
/// one line for Auto saying which device renders and why, and one line on an out-of-memory
/// fallback.
inline std::unique_ptr<Renderer> createRenderer(RenderDevice device, RendererLog log = nullptr)
{
  if (!log)
  {
    log = [](const std::string& line) { std::cerr << "amrdm: " << line << "\n"; };
  }
  if (device == RenderDevice::Cpu)
  {
    return std::unique_ptr<Renderer>(new CpuRenderer);
  }
  std::string reason;
  const bool haveCuda = cudaRenderingAvailable(&reason);
  if (device == RenderDevice::Cuda && !haveCuda)
  {
    throw std::runtime_error("CUDA rendering was requested, but " + reason);
  }
  if (!haveCuda)
  {
    log("device auto: rendering on the CPU (" + reason + ")");
    return std::unique_ptr<Renderer>(new CpuRenderer);
  }
#ifdef AMRDM_RENDERER_FACTORY_CUDA
  if (device == RenderDevice::Cuda)
  {
    return std::unique_ptr<Renderer>(new CudaRenderer);
  }
  std::unique_ptr<CudaRenderer> gpu;
  try
  {
    gpu.reset(new CudaRenderer);
  }
  catch (const std::exception& e)
  {
    log(std::string("device auto: rendering on the CPU (") + e.what() + ")");
    return std::unique_ptr<Renderer>(new CpuRenderer);
  }
  log("device auto: rendering on CUDA device " + gpu->deviceName());
  return std::unique_ptr<Renderer>(new FallbackRenderer(std::move(gpu), log));
#else
  return nullptr; // unreachable: haveCuda is false without CUDA
#endif
}

} // namespace amrdm
