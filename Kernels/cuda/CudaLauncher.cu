// CUDA launcher: device buffers (RAII), uploads of the dual mesh, and the point-sampling kernel.
// The kernel body is FieldSampler.h, the same code the CPU runs.
#include "cuda/CudaLauncher.h"

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
void check(cudaError_t status, const char* what)
{
  if (status != cudaSuccess)
  {
    throw std::runtime_error(
      std::string("CUDA: ") + what + " failed: " + cudaGetErrorString(status));
  }
}

/// Owns one device allocation.
template<typename T>
class DeviceBuffer
{
public:
  DeviceBuffer() = default;
  template<typename Allocator>
  explicit DeviceBuffer(const std::vector<T, Allocator>& host)
  {
    this->upload(host.data(), host.size());
  }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  ~DeviceBuffer() { cudaFree(this->Ptr); }

  void allocate(std::size_t n)
  {
    cudaFree(this->Ptr);
    this->Ptr = nullptr;
    this->Size = n;
    if (n > 0)
    {
      check(cudaMalloc(&this->Ptr, n * sizeof(T)), "cudaMalloc");
    }
  }
  void upload(const T* host, std::size_t n)
  {
    this->allocate(n);
    if (n > 0)
    {
      check(cudaMemcpy(this->Ptr, host, n * sizeof(T), cudaMemcpyHostToDevice), "upload");
    }
  }
  void download(T* host, std::size_t n) const
  {
    if (n > 0)
    {
      check(cudaMemcpy(host, this->Ptr, n * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }
  }
  T* get() const { return this->Ptr; }

private:
  T* Ptr = nullptr;
  std::size_t Size = 0;
};

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
  DeviceBuffer<float> levelWidth(mesh.levelWidth);
  DeviceBuffer<GridletHeader> gridlets(mesh.gridlets);
  DeviceBuffer<float> scalars(mesh.gridletScalars);
  DeviceBuffer<ElementVertex> vertices(mesh.vertices);
  mesh.validate(); // element kinds and indices the kernel can trust
  DeviceBuffer<std::uint32_t> indices[kElementKindCount];
  for (int k = 0; k < kElementKindCount; ++k)
  {
    indices[k].upload(mesh.elementIndices[k].data(), mesh.elementIndices[k].size());
  }
  DeviceBuffer<BvhNode> nodes(mesh.bvh.nodes);
  DeviceBuffer<std::uint32_t> prims(mesh.bvh.prims);
  DeviceBuffer<glm::vec3> devPoints;
  devPoints.upload(points, n);
  DeviceBuffer<float> devValues;
  devValues.allocate(n);
  DeviceBuffer<std::uint8_t> devHits;
  devHits.allocate(n);

  DualMeshView view;
  view.levelWidth = levelWidth.get();
  view.numLevels = static_cast<int>(mesh.levelWidth.size());
  view.gridlets = gridlets.get();
  view.gridletScalars = scalars.get();
  view.vertices = vertices.get();
  for (int k = 0; k < kElementKindCount; ++k)
  {
    view.elementIndices[k] = indices[k].get();
  }
  view.bvh.nodes = nodes.get();
  view.bvh.prims = prims.get();
  view.bvh.numNodes = static_cast<std::uint32_t>(mesh.bvh.nodes.size());

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
