// CUDA renderer: device buffers for the mesh, majorants, culling masks and transfer function;
// progressive accumulation on the device. See CudaRenderer.h. The kernels (one per integrator,
// one thread per pixel running samplePixelWith<I>(), the CPU's per-pixel code) live in the
// CudaRender*.cu translation units (CudaRenderKernel.h); this one holds no integrator code.
#include "cuda/CudaRenderer.h"

#include "cuda/CudaBuffers.h"
#include "cuda/CudaLauncher.h"
#include "cuda/CudaRenderKernel.h"
#include "render/PassCancellation.h"

#include <cuda_runtime.h>

#include <atomic>
#include <sstream>

namespace amrdm
{
namespace
{
using cuda::check;
using cuda::DeviceBuffer;

constexpr int kNumCounters = cuda::kNumPassCounters;
} // namespace

void cuda::launchRenderPass(const PassLaunch& launch)
{
  switch (launch.params.integrator) // one kernel per row of render/IntegratorList.h
  {
#define AMRDM_INTEGRATOR_CASE(type, ...)                                                           \
  case IntegratorType::type:                                                                       \
    return launchRenderPassWith<IntegratorType::type>(launch);
    AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_CASE)
#undef AMRDM_INTEGRATOR_CASE
  }
  return launchRenderPassWith<IntegratorType::PathTracer>(launch);
}

// --- GpuMemoryReport -------------------------------------------------------------------------

std::uint64_t GpuMemoryReport::computedTotal() const
{
  std::uint64_t t = 0;
  for (const Entry& e : this->entries)
    t += e.computed;
  return t;
}

std::int64_t GpuMemoryReport::measuredTotal() const
{
  std::int64_t t = 0;
  for (const Entry& e : this->entries)
    t += e.measured;
  return t;
}

const GpuMemoryReport::Entry* GpuMemoryReport::find(const std::string& category) const
{
  for (const Entry& e : this->entries)
    if (e.category == category)
      return &e;
  return nullptr;
}

std::string GpuMemoryReport::toJson() const
{
  std::ostringstream s;
  s << "{\"device\": \"" << this->deviceName << "\", \"deviceTotalBytes\": " << this->deviceTotal
    << ", \"deviceFreeBytes\": " << this->deviceFree << ", \"categories\": {";
  for (std::size_t i = 0; i < this->entries.size(); ++i)
  {
    s << (i ? ", " : "") << "\"" << this->entries[i].category
      << "\": {\"computed\": " << this->entries[i].computed
      << ", \"measured\": " << this->entries[i].measured << "}";
  }
  s << "}, \"computedTotal\": " << this->computedTotal()
    << ", \"measuredTotal\": " << this->measuredTotal() << "}";
  return s.str();
}

// --- CudaRenderer ------------------------------------------------------------------------------

struct CudaRenderer::Impl
{
  cuda::MemoryLedger ledger;
  std::string deviceName;

  // Host state (the same as CpuRenderer's).
  const DualMesh* mesh = nullptr;
  TransferFunction tf;
  bool hasTf = false;
  MajorantGrid majorants;
  PrimitiveCulling culling;
  glm::ivec3 requestedResolution{ 0 };
  int width = 0, height = 0;
  int passes = 0;
  PassCancellation cancellation; ///< a pass is one launch: a cancel during it keeps its samples

  // The dual mesh (uploaded by setMesh only).
  DeviceBuffer<float> levelWidth{ &ledger, cuda::MemGridletHeaders, "level widths" };
  DeviceBuffer<GridletHeader> gridlets{ &ledger, cuda::MemGridletHeaders, "gridlet headers" };
  DeviceBuffer<float> scalars{ &ledger, cuda::MemGridletScalars, "gridlet scalars" };
  DeviceBuffer<ElementVertex> vertices{ &ledger, cuda::MemElementVertices, "element vertices" };
  DeviceBuffer<std::uint32_t> indices[kElementKindCount] = {
#define AMRDM_ELEMENT_BUFFER(kind, name, ...) { &ledger, cuda::MemElementIndices, name " indices" },
    AMRDM_ELEMENTS(AMRDM_ELEMENT_BUFFER)
#undef AMRDM_ELEMENT_BUFFER
  };
  DeviceBuffer<BvhNode> nodes{ &ledger, cuda::MemBvh, "BVH nodes" };
  DeviceBuffer<std::uint32_t> prims{ &ledger, cuda::MemBvh, "BVH primitive references" };
  // Transfer-function derived.
  DeviceBuffer<std::uint8_t> nodeVisible{ &ledger, cuda::MemCullingMasks, "BVH node culling mask" };
  DeviceBuffer<std::uint8_t> slotVisible{ &ledger, cuda::MemCullingMasks, "BVH slot culling mask" };
  DeviceBuffer<float> majorant{ &ledger, cuda::MemMajorantGrid, "majorant grid" };
  // Mesh and resolution derived (uploaded with each new majorant grid).
  DeviceBuffer<float> cellWidth{ &ledger, cuda::MemMajorantGrid, "macrocell cell widths" };
  DeviceBuffer<glm::vec4> table{ &ledger, cuda::MemTransferFunction, "transfer-function table" };
  // Per frame.
  DeviceBuffer<double> sum{ &ledger, cuda::MemFrameBuffers, "accumulation sum" }; // 4 per pixel
  DeviceBuffer<double> sumSq{ &ledger, cuda::MemFrameBuffers, "accumulation sum of squares" };
  DeviceBuffer<std::uint32_t> count{ &ledger, cuda::MemFrameBuffers, "sample counts" };
  DeviceBuffer<float> depthMaxT{ &ledger, cuda::MemDepthBuffers, "depth (max t) buffer" };
  DeviceBuffer<float> minT{ &ledger, cuda::MemDepthBuffers, "min t buffer" };
  DeviceBuffer<unsigned long long> counters{ &ledger, cuda::MemCounters, "work counters" };

  /// Uploads what the transfer function derives: majorants and culling masks.
  void uploadDerived(int threads)
  {
    updateMajorants(this->majorants, this->tf.view(), threads);
    updatePrimitiveVisibility(this->culling, this->tf.view(), threads);
    this->majorant.upload(this->majorants.majorant.data(), this->majorants.majorant.size());
    this->nodeVisible.upload(this->culling.nodeVisible.data(), this->culling.nodeVisible.size());
    this->slotVisible.upload(this->culling.slotVisible.data(), this->culling.slotVisible.size());
  }

  void resetAccumulation()
  {
    this->sum.zero();
    this->sumSq.zero();
    this->count.zero();
    this->counters.zero();
    this->passes = 0;
  }
};

CudaRenderer::CudaRenderer()
  : P(new Impl)
{
  std::string reason;
  if (!cuda::deviceAvailable(&reason))
  {
    throw std::runtime_error(reason);
  }
  check(cudaSetDevice(0), "cudaSetDevice(0)");
  check(cudaFree(nullptr), "creating the CUDA context"); // so no upload is charged for it
  cudaDeviceProp prop;
  check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
  this->P->deviceName = prop.name;
  this->P->counters.resize(kNumCounters);
  this->P->counters.zero();
}

CudaRenderer::~CudaRenderer() = default;

void CudaRenderer::setMemoryLimit(std::uint64_t bytes)
{
  this->P->ledger.limit = bytes;
}

std::string CudaRenderer::deviceName() const
{
  return this->P->deviceName;
}

const MajorantGrid& CudaRenderer::majorantGrid() const
{
  return this->P->majorants;
}

const PrimitiveCulling& CudaRenderer::primitiveCulling() const
{
  return this->P->culling;
}

void CudaRenderer::setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution, int threads)
{
  Impl& p = *this->P;
  if (mesh)
  {
    mesh->validate(); // element kinds and indices the kernels can trust
  }
  p.mesh = mesh;
  p.requestedResolution = majorantResolution;
  p.majorants = mesh ? buildMajorantRanges(*mesh, majorantResolution, threads) : MajorantGrid();
  p.cellWidth.upload(p.majorants.cellWidth.data(), p.majorants.cellWidth.size());
  p.culling = mesh ? buildPrimitiveRanges(*mesh, threads) : PrimitiveCulling();

  // Upload the dual mesh.
  static const DualMesh empty;
  const DualMesh& m = mesh ? *mesh : empty;
  p.levelWidth.upload(m.levelWidth.data(), m.levelWidth.size());
  p.gridlets.upload(m.gridlets.data(), m.gridlets.size());
  p.scalars.upload(m.gridletScalars.data(), m.gridletScalars.size());
  p.vertices.upload(m.vertices.data(), m.vertices.size());
  for (int k = 0; k < kElementKindCount; ++k)
  {
    p.indices[k].upload(m.elementIndices[k].data(), m.elementIndices[k].size());
  }
  p.nodes.upload(m.bvh.nodes.data(), m.bvh.nodes.size());
  p.prims.upload(m.bvh.prims.data(), m.bvh.prims.size());
  if (p.hasTf)
  {
    p.uploadDerived(threads);
  }
  this->reset();
}

void CudaRenderer::setTransferFunction(const TransferFunction& tf, int threads)
{
  Impl& p = *this->P;
  p.tf = tf;
  p.hasTf = true;
  p.table.upload(p.tf.table.data(), p.tf.table.size());
  p.uploadDerived(threads);
  this->reset();
}

void CudaRenderer::reset()
{
  this->P->resetAccumulation();
}

void CudaRenderer::cancel()
{
  this->P->cancellation.request();
}

bool CudaRenderer::renderPass(const RenderParams& userParams,
  const float* depthMaxT,
  const float* minT)
{
  Impl& p = *this->P;
  if (!p.mesh || !p.hasTf || userParams.width <= 0 || userParams.height <= 0)
  {
    return true;
  }
  const std::size_t n = std::size_t(userParams.width) * std::size_t(userParams.height);
  if (userParams.width != p.width || userParams.height != p.height)
  {
    p.width = userParams.width;
    p.height = userParams.height;
    p.sum.resize(4 * n);
    p.sumSq.resize(4 * n);
    p.count.resize(n);
    this->reset();
  }
  if (userParams.majorantResolution != p.requestedResolution)
  {
    // Majorant ranges depend on the mesh and the resolution only: no mesh re-upload.
    p.requestedResolution = userParams.majorantResolution;
    p.majorants = buildMajorantRanges(*p.mesh, p.requestedResolution, userParams.threads);
    p.cellWidth.upload(p.majorants.cellWidth.data(), p.majorants.cellWidth.size());
    p.uploadDerived(userParams.threads);
    this->reset();
  }
  if (depthMaxT)
  {
    p.depthMaxT.upload(depthMaxT, n);
  }
  if (minT)
  {
    p.minT.upload(minT, n);
  }

  const RenderParams params = resolveRenderParams(userParams, *p.mesh);
  const glm::vec3 spacing(p.mesh->finestSpacing);
  DualMeshMedium medium;
  DualMeshView& view = medium.mesh;
  view.levelWidth = p.levelWidth.get();
  view.numLevels = static_cast<int>(p.levelWidth.size());
  view.gridlets = p.gridlets.get();
  view.gridletScalars = p.scalars.get();
  view.vertices = p.vertices.get();
  for (int k = 0; k < kElementKindCount; ++k)
  {
    view.elementIndices[k] = p.indices[k].get();
  }
  view.bvh.nodes = p.nodes.get();
  view.bvh.prims = p.prims.get();
  view.bvh.numNodes = static_cast<std::uint32_t>(p.nodes.size());
  if (cullingEnabled(params) && p.slotVisible.size() > 0)
  {
    view.bvh.nodeVisible = p.nodeVisible.get();
    view.bvh.slotVisible = p.slotVisible.get();
  }
  medium.tf = p.tf.view();
  medium.tf.table = p.table.get();
  medium.elementTest = params.elementTest;
  medium.origin = glm::vec3(p.mesh->origin);
  medium.invSpacing = 1.0f / spacing;
  medium.countPrimitiveTests = integratorInfo(params.integrator).countsPrimitiveTests;
  MajorantGridView grid = p.majorants.view();
  grid.majorant = p.majorant.get();
  grid.cellWidth = p.cellWidth.size() > 0 ? p.cellWidth.get() : nullptr;

  cuda::PassLaunch launch;
  launch.medium = medium;
  launch.grid = grid;
  launch.params = params;
  launch.frame = std::uint32_t(p.passes);
  launch.depthMaxT = depthMaxT ? p.depthMaxT.get() : nullptr;
  launch.minT = minT ? p.minT.get() : nullptr;
  launch.sum = p.sum.get();
  launch.sumSq = p.sumSq.get();
  launch.count = p.count.get();
  launch.counters = p.counters.get();
  p.cancellation.begin();
  cuda::launchRenderPass(launch);
  check(cudaGetLastError(), "launching the render-pass kernel");
  check(cudaDeviceSynchronize(), "the render-pass kernel");
  ++p.passes;
  return !p.cancellation.end(); // a pass is one launch: a cancel during it keeps its samples
}

std::vector<std::uint32_t> CudaRenderer::sampleCounts() const
{
  std::vector<std::uint32_t> counts(this->P->count.size());
  this->P->count.download(counts.data(), counts.size());
  return counts;
}

std::vector<float> CudaRenderer::image() const
{
  const Impl& p = *this->P;
  std::vector<glm::dvec4> sum(p.sum.size() / 4);
  p.sum.download(reinterpret_cast<double*>(sum.data()), p.sum.size());
  const std::vector<std::uint32_t> counts = this->sampleCounts();
  std::vector<float> out(sum.size() * 4, 0.0f);
  for (std::size_t i = 0; i < sum.size(); ++i)
  {
    const glm::vec4 m = accumulatedMean(sum[i], counts[i]);
    for (int c = 0; c < 4; ++c)
      out[4 * i + c] = m[c];
  }
  return out;
}

std::vector<float> CudaRenderer::varianceOfMean() const
{
  const Impl& p = *this->P;
  std::vector<glm::dvec4> sum(p.sum.size() / 4), sumSq(p.sumSq.size() / 4);
  p.sum.download(reinterpret_cast<double*>(sum.data()), p.sum.size());
  p.sumSq.download(reinterpret_cast<double*>(sumSq.data()), p.sumSq.size());
  const std::vector<std::uint32_t> counts = this->sampleCounts();
  std::vector<float> out(sum.size() * 4, 0.0f);
  for (std::size_t i = 0; i < sum.size(); ++i)
  {
    const glm::vec4 v = accumulatedVarianceOfMean(sum[i], sumSq[i], counts[i]);
    for (int c = 0; c < 4; ++c)
      out[4 * i + c] = v[c];
  }
  return out;
}

RenderStats CudaRenderer::stats() const
{
  unsigned long long c[kNumCounters] = {};
  this->P->counters.download(c, kNumCounters);
  RenderStats s;
  s.samples = c[0];
  s.steps = c[1];
  s.primitiveTests = c[2];
  s.stepLimitHits = c[3];
  s.majorantViolations = c[4];
  s.passes = this->P->passes;
  return s;
}

GpuMemoryReport CudaRenderer::memoryReport() const
{
  GpuMemoryReport r;
  for (int c = 0; c < cuda::MemCategoryCount; ++c)
  {
    GpuMemoryReport::Entry e;
    e.category = cuda::memoryCategoryName(c);
    e.computed = this->P->ledger.computed[c];
    e.measured = this->P->ledger.measured[c];
    r.entries.push_back(e);
  }
  r.deviceName = this->P->deviceName;
  std::size_t freeBytes = 0, totalBytes = 0;
  check(cudaMemGetInfo(&freeBytes, &totalBytes), "cudaMemGetInfo");
  r.deviceFree = freeBytes;
  r.deviceTotal = totalBytes;
  return r;
}

std::string CudaRenderer::deviceMemoryJson() const
{
  return this->memoryReport().toJson();
}

} // namespace amrdm
