// The renderer factory (see RendererFactory.h). Compiled once into amrdm_renderers, which links
// amrdm_cuda when nvcc built it: whether CUDA exists is decided by this library's build, not by
// the macros of whoever includes the header. Host code.
#include "render/RendererFactory.h"

#include "render/CpuRenderer.h"

#if defined(AMRDM_HAVE_CUDA) && AMRDM_HAVE_CUDA
#include "cuda/CudaLauncher.h"
#include "cuda/CudaRenderer.h"
#define AMRDM_RENDERER_FACTORY_CUDA 1
#endif

#include <iostream>
#include <stdexcept>

namespace amrdm
{

bool cudaRenderingAvailable(std::string* reason)
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

bool cudaSupportBuilt()
{
#ifdef AMRDM_RENDERER_FACTORY_CUDA
  return true;
#else
  return false;
#endif
}

namespace
{
#ifdef AMRDM_RENDERER_FACTORY_CUDA
/// Auto device with CUDA: a CudaRenderer that hands over to a CpuRenderer when the device runs
/// out of memory, replaying the mesh, transfer function and proxy.
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
  void setProxy(const DualMesh* proxy,
    const glm::vec3& lo,
    const glm::vec3& hi,
    int threads) override
  {
    this->Proxy = proxy;
    this->ProxyLo = lo;
    this->ProxyHi = hi;
    this->guarded([&] { this->Active->setProxy(proxy, lo, hi, threads); });
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
  std::uint64_t accelerationBytes() const override { return this->Active->accelerationBytes(); }

private:
  template<typename F>
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
      if (this->Proxy)
      {
        this->Active->setProxy(this->Proxy, this->ProxyLo, this->ProxyHi, this->Threads);
      }
      f();
    }
  }

  std::unique_ptr<Renderer> Active;
  RendererLog Log;
  const DualMesh* Mesh = nullptr;
  const DualMesh* Proxy = nullptr;
  glm::vec3 ProxyLo{ 0.0f }, ProxyHi{ 0.0f };
  glm::ivec3 Resolution{ 0 };
  int Threads = 0;
  TransferFunction Tf;
  bool HasTf = false;
};
#endif

} // namespace

std::unique_ptr<Renderer> withCpuFallback(std::unique_ptr<Renderer> gpu, RendererLog log)
{
#ifdef AMRDM_RENDERER_FACTORY_CUDA
  return std::unique_ptr<Renderer>(new FallbackRenderer(std::move(gpu), std::move(log)));
#else
  (void)log;
  return gpu;
#endif
}

std::unique_ptr<Renderer> createRenderer(RenderDevice device, RendererLog log)
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
  return withCpuFallback(std::move(gpu), log);
#else
  return nullptr; // unreachable: haveCuda is false without CUDA
#endif
}

} // namespace amrdm
