// RAII device buffers with memory accounting, and the one device copy of a dual mesh
// (DeviceDualMesh), for every CUDA entry (the renderer, the point sampler). CUDA-only header:
// include it from .cu files only (it includes cuda_runtime.h).
//
// Every allocation is booked in a MemoryLedger under a category: `computed` adds the bytes we
// asked for, `measured` adds the drop in cudaMemGetInfo's free memory across the cudaMalloc (and
// subtracts the rise across the cudaFree), so both stay net values while buffers are reallocated.
#pragma once

#include "cuda/GpuMemoryReport.h" // For GpuOutOfMemory
#include "mesh/DualMesh.h"

#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace amrdm
{
namespace cuda
{

/// Throws std::runtime_error "CUDA: <what> failed: <reason>" unless status is cudaSuccess.
inline void check(cudaError_t status, const char* what)
{
  if (status != cudaSuccess)
  {
    throw std::runtime_error(
      std::string("CUDA: ") + what + " failed: " + cudaGetErrorString(status));
  }
}

inline std::string formatBytes(std::uint64_t bytes)
{
  char text[64];
  std::snprintf(text,
    sizeof(text),
    "%llu B = %.1f MiB",
    static_cast<unsigned long long>(bytes),
    double(bytes) / (1024.0 * 1024.0));
  return text;
}

/// Device memory categories (GpuMemoryReport::entries, in this order).
enum MemoryCategory : int
{
  MemGridletScalars = 0,
  MemGridletHeaders,
  MemElementVertices,
  MemElementIndices,
  MemBvh,
  MemCullingMasks,
  MemMajorantGrid,
  MemTransferFunction,
  MemFrameBuffers,
  MemDepthBuffers,
  MemCounters,
  MemCategoryCount
};

inline const char* memoryCategoryName(int c)
{
  static const char* names[MemCategoryCount] = { "gridletScalars",
    "gridletHeaders",
    "elementVertices",
    "elementIndices",
    "bvh",
    "cullingMasks",
    "majorantGrid",
    "transferFunction",
    "frameBuffers",
    "depthBuffers",
    "counters" };
  return c >= 0 && c < MemCategoryCount ? names[c] : "other";
}

struct MemoryLedger
{
  std::uint64_t computed[MemCategoryCount] = {};
  std::int64_t measured[MemCategoryCount] = {};
  std::uint64_t limit = 0; ///< > 0: allocations beyond this many bytes in all fail (tests)

  std::uint64_t computedTotal() const
  {
    std::uint64_t t = 0;
    for (std::uint64_t c : this->computed)
      t += c;
    return t;
  }
};

inline std::uint64_t freeDeviceMemory()
{
  std::size_t freeBytes = 0, totalBytes = 0;
  check(cudaMemGetInfo(&freeBytes, &totalBytes), "cudaMemGetInfo");
  return freeBytes;
}

/// One device array of T. Not copyable; freed on destruction. resize() keeps the allocation
/// when the element count does not change (contents are then kept, otherwise undefined).
template<typename T>
class DeviceBuffer
{
public:
  DeviceBuffer(MemoryLedger* ledger, MemoryCategory category, const char* name)
    : Ledger(ledger)
    , Category(category)
    , Name(name)
  {
  }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  ~DeviceBuffer() { this->release(); }

  void resize(std::size_t n)
  {
    if (n == this->Count && (n == 0 || this->Ptr))
    {
      return;
    }
    this->release();
    if (n == 0)
    {
      return;
    }
    const std::uint64_t bytes = std::uint64_t(n) * sizeof(T);
    if (this->Ledger && this->Ledger->limit > 0 &&
        this->Ledger->computedTotal() + bytes > this->Ledger->limit)
    {
      throw GpuOutOfMemory(std::string("CUDA: out of device memory allocating ") + this->Name +
                           " (" + formatBytes(bytes) + "; over the renderer's memory limit of " +
                           formatBytes(this->Ledger->limit) + ")");
    }
    const std::uint64_t before = freeDeviceMemory();
    void* p = nullptr;
    const cudaError_t status = cudaMalloc(&p, bytes);
    if (status == cudaErrorMemoryAllocation)
    {
      cudaGetLastError(); // not sticky: clear it so later calls are unaffected
      std::size_t freeBytes = 0, totalBytes = 0;
      cudaMemGetInfo(&freeBytes, &totalBytes);
      throw GpuOutOfMemory(std::string("CUDA: out of device memory allocating ") + this->Name +
                           " (" + formatBytes(bytes) + "; " + formatBytes(freeBytes) + " free of " +
                           formatBytes(totalBytes) + ")");
    }
    check(status,
      (std::string("cudaMalloc of ") + this->Name + " (" + formatBytes(bytes) + ")").c_str());
    this->Ptr = static_cast<T*>(p);
    this->Count = n;
    if (this->Ledger)
    {
      this->Ledger->computed[this->Category] += bytes;
      this->Ledger->measured[this->Category] +=
        std::int64_t(before) - std::int64_t(freeDeviceMemory());
    }
  }
  void upload(const T* host, std::size_t n)
  {
    this->resize(n);
    if (n > 0)
    {
      check(cudaMemcpy(this->Ptr, host, n * sizeof(T), cudaMemcpyHostToDevice),
        (std::string("upload of ") + this->Name).c_str());
    }
  }
  void download(T* host, std::size_t n) const
  {
    if (n > 0)
    {
      check(cudaMemcpy(host, this->Ptr, n * sizeof(T), cudaMemcpyDeviceToHost),
        (std::string("download of ") + this->Name).c_str());
    }
  }
  void zero()
  {
    if (this->Count > 0)
    {
      check(cudaMemset(this->Ptr, 0, this->Count * sizeof(T)),
        (std::string("clearing ") + this->Name).c_str());
    }
  }
  void release()
  {
    if (!this->Ptr)
    {
      return;
    }
    const std::uint64_t bytes = std::uint64_t(this->Count) * sizeof(T);
    std::size_t before = 0, after = 0, total = 0;
    const bool measure = this->Ledger && cudaMemGetInfo(&before, &total) == cudaSuccess;
    cudaFree(this->Ptr); // never throws: also runs from destructors
    if (measure && cudaMemGetInfo(&after, &total) == cudaSuccess)
    {
      this->Ledger->measured[this->Category] -= std::int64_t(after) - std::int64_t(before);
    }
    if (this->Ledger)
    {
      this->Ledger->computed[this->Category] -= bytes;
    }
    this->Ptr = nullptr;
    this->Count = 0;
  }
  T* get() const { return this->Ptr; }
  std::size_t size() const { return this->Count; }

private:
  MemoryLedger* Ledger = nullptr;
  MemoryCategory Category;
  const char* Name;
  T* Ptr = nullptr;
  std::size_t Count = 0;
};

/// The dual mesh on the device (gridlet headers and scalars, stitching vertices and indices, BVH
/// nodes and primitive references): upload() validates the mesh (element kinds and indices the
/// kernels can trust) and copies it, reusing buffers whose size is kept; view() is the
/// DualMeshView over the device copies (no culling masks).
struct DeviceDualMesh
{
  explicit DeviceDualMesh(MemoryLedger* ledger)
    : levelWidth(ledger, MemGridletHeaders, "level widths")
    , gridlets(ledger, MemGridletHeaders, "gridlet headers")
    , scalars(ledger, MemGridletScalars, "gridlet scalars")
    , vertices(ledger, MemElementVertices, "element vertices")
    , indices{
#define AMRDM_ELEMENT_BUFFER(kind, name, ...) { ledger, MemElementIndices, name " indices" },
        AMRDM_ELEMENTS(AMRDM_ELEMENT_BUFFER)
#undef AMRDM_ELEMENT_BUFFER
      }
    , nodes(ledger, MemBvh, "BVH nodes")
    , prims(ledger, MemBvh, "BVH primitive references")
  {
  }

  void upload(const DualMesh& m)
  {
    m.validate();
    this->levelWidth.upload(m.levelWidth.data(), m.levelWidth.size());
    this->gridletOrigin = m.gridletOrigin;
    this->gridlets.upload(m.gridlets.data(), m.gridlets.size());
    this->scalars.upload(m.gridletScalars.data(), m.gridletScalars.size());
    this->vertices.upload(m.vertices.data(), m.vertices.size());
    for (int k = 0; k < kElementKindCount; ++k)
    {
      this->indices[k].upload(m.elementIndices[k].data(), m.elementIndices[k].size());
    }
    this->nodes.upload(m.bvh.nodes.data(), m.bvh.nodes.size());
    this->prims.upload(m.bvh.prims.data(), m.bvh.prims.size());
  }

  DualMeshView view() const
  {
    DualMeshView v;
    v.levelWidth = this->levelWidth.get();
    v.numLevels = static_cast<int>(this->levelWidth.size());
    v.gridletOrigin = this->gridletOrigin;
    v.gridlets = this->gridlets.get();
    v.gridletScalars = this->scalars.get();
    v.vertices = this->vertices.get();
    for (int k = 0; k < kElementKindCount; ++k)
    {
      v.elementIndices[k] = this->indices[k].get();
    }
    v.bvh.nodes = this->nodes.get();
    v.bvh.prims = this->prims.get();
    v.bvh.numNodes = static_cast<std::uint32_t>(this->nodes.size());
    return v;
  }

  DeviceBuffer<float> levelWidth;
  DeviceBuffer<GridletHeader> gridlets;
  float gridletOrigin = 0.5f; ///< DualMesh::gridletOrigin of the uploaded mesh
  DeviceBuffer<float> scalars;
  DeviceBuffer<ElementVertex> vertices;
  DeviceBuffer<std::uint32_t> indices[kElementKindCount];
  DeviceBuffer<BvhNode> nodes;
  DeviceBuffer<std::uint32_t> prims;
};

} // namespace cuda
} // namespace amrdm
