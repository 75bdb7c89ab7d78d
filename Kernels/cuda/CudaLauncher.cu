// CUDA launcher: the device check and the point-sampling kernel, on the renderer's device
// buffers and dual-mesh upload (CudaBuffers.h). The kernel body is FieldSampler.h, the same code
// the CPU runs.
#include "cuda/CudaLauncher.h"

#include "cuda/CudaBuffers.h"

#include "sampling/FieldSampler.h"

#include <cuda_runtime.h>

#include <stdexcept>
#include <vector>

namespace amrdm
{
namespace cuda
{
namespace
{
__global__ void samplePointsKernel(DualMeshView mesh,
  const glm::vec3* points,
  std::size_t n,
  ElementTestParams params,
  float* values,
  std::uint8_t* hits)
{
  const std::size_t i = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= n)
  {
    return;
  }
  float v = 0.0f;
  const bool hit = sampleField(mesh, points[i], params, v);
  values[i] = hit ? v : 0.0f;
  hits[i] = hit ? 1 : 0;
}
} // namespace

bool deviceAvailable(std::string* reason)
{
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status == cudaSuccess && count > 0)
  {
    return true;
  }
  cudaGetLastError(); // not sticky: clear it so later calls are unaffected
  // No device is the ordinary case of a machine without a GPU: say so plainly. Without any
  // driver (cudaDriverGetVersion gives 0) the runtime reports an "insufficient driver", which
  // means the same here. A driver that is there but too old, or any other failure, keeps
  // CUDA's own text.
  int driverVersion = 0;
  const bool noDriver = status == cudaErrorInsufficientDriver &&
                        cudaDriverGetVersion(&driverVersion) == cudaSuccess && driverVersion == 0;
  if (reason)
  {
    if (status == cudaSuccess || status == cudaErrorNoDevice)
    {
      *reason = "no CUDA device found";
    }
    else if (noDriver)
    {
      *reason = "no CUDA device found (no CUDA driver is installed)";
    }
    else
    {
      *reason = std::string("no usable CUDA device: ") + cudaGetErrorString(status);
    }
  }
  return false;
}

void samplePoints(const DualMesh& mesh,
  const glm::vec3* points,
  std::size_t n,
  const ElementTestParams& params,
  float* values,
  std::uint8_t* hits)
{
  DeviceDualMesh device(nullptr);
  device.upload(mesh); // validates it first: element kinds and indices the kernel can trust
  DeviceBuffer<glm::vec3> devPoints(nullptr, MemCounters, "sample points");
  devPoints.upload(points, n);
  DeviceBuffer<float> devValues(nullptr, MemCounters, "sampled values");
  devValues.resize(n);
  DeviceBuffer<std::uint8_t> devHits(nullptr, MemCounters, "sample hit flags");
  devHits.resize(n);
  const DualMeshView view = device.view();

  if (n > 0)
  {
    const unsigned block = 128;
    const unsigned grid = static_cast<unsigned>((n + block - 1) / block);
    samplePointsKernel<<<grid, block>>>(
      view, devPoints.get(), n, params, devValues.get(), devHits.get());
    check(cudaGetLastError(), "samplePointsKernel launch");
    check(cudaDeviceSynchronize(), "samplePointsKernel");
  }
  devValues.download(values, n);
  devHits.download(hits, n);
}

} // namespace cuda
} // namespace amrdm
