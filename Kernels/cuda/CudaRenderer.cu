// CUDA renderer: the device copies of the RenderScene (mesh, majorants, culling masks, transfer
// function) and progressive accumulation on the device. See CudaRenderer.h. The kernels (one per
// integrator, one thread per pixel running samplePixelWith<I>(), the CPU's per-pixel code) live in
// the CudaRender*.cu translation units (CudaRenderKernel.h); this one holds no integrator code.
#include "cuda/CudaRenderer.h"

#include "cuda/CudaBuffers.h"
#include "cuda/CudaLauncher.h"
#include "cuda/CudaRenderKernel.h"

#include <cuda_runtime.h>

namespace amrdm
{
namespace
{
using cuda::check;
using cuda::DeviceBuffer;

constexpr int kNumCounters = cuda::kNumPassCounters;

/// The device copy of a whole majorant grid (majorants, cell widths, value ranges): the
/// composite grid of a proxy scene, uploaded with every change of the scene's grids.
struct DeviceGrid
{
  DeviceGrid(cuda::MemoryLedger* ledger, const char* name)
    : majorant(ledger, cuda::MemMajorantGrid, name)
    , cellWidth(ledger, cuda::MemMajorantGrid, name)
    , range(ledger, cuda::MemMajorantGrid, name)
  {
  }
  void upload(const MajorantGrid& g)
  {
    this->majorant.upload(g.majorant.data(), g.majorant.size());
    this->cellWidth.upload(g.cellWidth.data(), g.cellWidth.size());
    this->range.upload(g.range.data(), g.range.size());
  }
  /// g's view (the grid these buffers hold) on the device copies.
  MajorantGridView view(const MajorantGrid& g) const
  {
    MajorantGridView v = g.view();
    v.majorant = this->majorant.size() > 0 ? this->majorant.get() : nullptr;
    v.cellWidth = this->cellWidth.size() > 0 ? this->cellWidth.get() : nullptr;
    v.range = v.range && this->range.size() > 0 ? this->range.get() : nullptr;
    return v;
  }
  DeviceBuffer<float> majorant;
  DeviceBuffer<float> cellWidth;
  DeviceBuffer<glm::vec2> range;
};
} // namespace

void cuda::launchRenderPass(const PassLaunch& launch)
{
  // One kernel per row of render/IntegratorList.h.
  withIntegrator(launch.params.integrator,
    [&](auto integrator) { launchRenderPassWith<decltype(integrator)::value>(launch); });
}

struct CudaRenderer::Impl
{
  explicit Impl(const RenderScene& s)
    : scene(s)
  {
  }
  cuda::MemoryLedger ledger;
  std::string deviceName;
  const RenderScene& scene; ///< the host scene (SceneRenderer's); below are its device copies

  cuda::DeviceDualMesh mesh{ &ledger };  // uploaded by setMesh only
  cuda::DeviceDualMesh proxy{ &ledger }; // uploaded by setProxy only (DistributionMode Proxy)
  // Transfer-function derived.
  DeviceBuffer<std::uint8_t> nodeVisible{ &ledger, cuda::MemCullingMasks, "BVH node culling mask" };
  DeviceBuffer<std::uint8_t> slotVisible{ &ledger, cuda::MemCullingMasks, "BVH slot culling mask" };
  DeviceBuffer<float> majorant{ &ledger, cuda::MemMajorantGrid, "majorant grid" };
  // Mesh and resolution derived (uploaded with each new majorant grid).
  DeviceBuffer<float> cellWidth{ &ledger, cuda::MemMajorantGrid, "macrocell cell widths" };
  DeviceBuffer<glm::vec2> range{ &ledger, cuda::MemMajorantGrid, "macrocell value ranges" };
  DeviceBuffer<glm::vec4> table{ &ledger, cuda::MemTransferFunction, "transfer-function table" };
  /// The scene's composite grid (region inside its box, proxy outside): empty without a proxy.
  DeviceGrid composite{ &ledger, "composite" };
  // Per frame.
  DeviceBuffer<double> sum{ &ledger, cuda::MemFrameBuffers, "accumulation sum" }; // 4 per pixel
  DeviceBuffer<double> sumSq{ &ledger, cuda::MemFrameBuffers, "accumulation sum of squares" };
  DeviceBuffer<std::uint32_t> count{ &ledger, cuda::MemFrameBuffers, "sample counts" };
  DeviceBuffer<float> depthMaxT{ &ledger, cuda::MemDepthBuffers, "depth (max t) buffer" };
  DeviceBuffer<float> minT{ &ledger, cuda::MemDepthBuffers, "min t buffer" };
  DeviceBuffer<unsigned long long> counters{ &ledger, cuda::MemCounters, "work counters" };

  /// Uploads the scene's majorants (with `widths`: and the grid's cell widths) and, with
  /// `masks`, its culling masks; the composite grid (proxy) whole, when there is one.
  void uploadGrids(bool widths, bool masks)
  {
    const MajorantGrid& g = this->scene.majorantGrid();
    if (widths)
    {
      this->cellWidth.upload(g.cellWidth.data(), g.cellWidth.size());
      this->range.upload(g.range.data(), g.range.size());
    }
    this->composite.upload(this->scene.compositeMajorantGrid());
    if (!this->scene.hasTransferFunction())
    {
      return;
    }
    this->majorant.upload(g.majorant.data(), g.majorant.size());
    if (masks)
    {
      const PrimitiveCulling& c = this->scene.primitiveCulling();
      this->nodeVisible.upload(c.nodeVisible.data(), c.nodeVisible.size());
      this->slotVisible.upload(c.slotVisible.data(), c.slotVisible.size());
    }
  }

  /// The scene's medium and grid views for (resolved) `params`, on the device copies: the
  /// region's mesh, or the composite medium and grid when the pass sees the proxy.
  cuda::PassLaunch launchFor(const RenderParams& params) const
  {
    cuda::PassLaunch launch;
    launch.params = params;
    launch.proxy = this->scene.seesProxy(params);
    if (launch.proxy)
    {
      launch.medium = this->scene.compositeMedium(params);
      launch.medium.outer.mesh = this->proxy.view(); // the proxy is never culled
      launch.medium.outer.tf.table = this->table.get();
      launch.grid = this->composite.view(this->scene.compositeMajorantGrid());
    }
    else
    {
      launch.medium.inner = this->scene.medium(params);
      launch.grid = this->scene.majorantGrid().view();
      launch.grid.majorant = this->majorant.get();
      launch.grid.cellWidth = this->cellWidth.size() > 0 ? this->cellWidth.get() : nullptr;
      launch.grid.range = launch.grid.range && this->range.size() > 0 ? this->range.get() : nullptr;
    }
    DualMeshMedium& inner = launch.medium.inner;
    inner.mesh = this->mesh.view();
    if (cullingEnabled(params) && this->slotVisible.size() > 0)
    {
      inner.mesh.bvh.nodeVisible = this->nodeVisible.get();
      inner.mesh.bvh.slotVisible = this->slotVisible.get();
    }
    inner.tf.table = this->table.get();
    return launch;
  }
};

CudaRenderer::CudaRenderer()
  : P(new Impl(this->scene()))
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

void CudaRenderer::sceneChanged(SceneChange what)
{
  Impl& p = *this->P;
  static const DualMesh empty;
  switch (what)
  {
    case SceneChange::Mesh:
      p.mesh.upload(p.scene.mesh() ? *p.scene.mesh() : empty);
      return p.uploadGrids(true, true);
    case SceneChange::TransferFunction:
      p.table.upload(
        p.scene.transferFunction().table.data(), p.scene.transferFunction().table.size());
      return p.uploadGrids(false, true);
    case SceneChange::Proxy:
      p.proxy.upload(p.scene.proxy() ? *p.scene.proxy() : empty);
      return p.composite.upload(p.scene.compositeMajorantGrid());
    case SceneChange::MajorantResolution:
      return p.uploadGrids(true, false); // the mesh and the culling masks are unchanged
  }
}

void CudaRenderer::resizeAccumulation(int width, int height)
{
  const std::size_t n = std::size_t(width) * std::size_t(height);
  this->P->sum.resize(4 * n);
  this->P->sumSq.resize(4 * n);
  this->P->count.resize(n);
}

void CudaRenderer::clearAccumulation()
{
  this->P->sum.zero();
  this->P->sumSq.zero();
  this->P->count.zero();
  this->P->counters.zero();
}

void CudaRenderer::runPass(const RenderParams& params, const float* depthMaxT, const float* minT)
{
  Impl& p = *this->P;
  const std::size_t n = std::size_t(params.width) * std::size_t(params.height);
  if (depthMaxT)
  {
    p.depthMaxT.upload(depthMaxT, n);
  }
  if (minT)
  {
    p.minT.upload(minT, n);
  }
  cuda::PassLaunch launch = p.launchFor(params);
  launch.frame = std::uint32_t(this->passes());
  launch.depthMaxT = depthMaxT ? p.depthMaxT.get() : nullptr;
  launch.minT = minT ? p.minT.get() : nullptr;
  launch.sum = p.sum.get();
  launch.sumSq = p.sumSq.get();
  launch.count = p.count.get();
  launch.counters = p.counters.get();
  cuda::launchRenderPass(launch);
  check(cudaGetLastError(), "launching the render-pass kernel");
  check(cudaDeviceSynchronize(), "the render-pass kernel");
}

std::vector<std::uint32_t> CudaRenderer::sampleCounts() const
{
  std::vector<std::uint32_t> counts(this->P->count.size());
  this->P->count.download(counts.data(), counts.size());
  return counts;
}

std::vector<float> CudaRenderer::image() const
{
  std::vector<glm::dvec4> sum(this->P->sum.size() / 4);
  this->P->sum.download(reinterpret_cast<double*>(sum.data()), this->P->sum.size());
  return accumulatedImage(sum.data(), nullptr, this->sampleCounts().data(), sum.size());
}

std::vector<float> CudaRenderer::varianceOfMean() const
{
  const Impl& p = *this->P;
  std::vector<glm::dvec4> sum(p.sum.size() / 4), sumSq(p.sumSq.size() / 4);
  p.sum.download(reinterpret_cast<double*>(sum.data()), p.sum.size());
  p.sumSq.download(reinterpret_cast<double*>(sumSq.data()), p.sumSq.size());
  return accumulatedImage(sum.data(), sumSq.data(), this->sampleCounts().data(), sum.size());
}

RenderStats CudaRenderer::stats() const
{
  unsigned long long c[kNumCounters] = {};
  this->P->counters.download(c, kNumCounters);
  RenderStats s;
  s.samples = c[0];
  const unsigned long long* next = c + 1; // core/WorkCounters.h's order, as the kernel adds them
#define AMRDM_STATS_COUNTER(name, doc) s.name = *next++;
  AMRDM_WORK_COUNTERS(AMRDM_STATS_COUNTER)
#undef AMRDM_STATS_COUNTER
  s.passes = this->passes();
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
