// The device-agnostic renderer interface: CpuRenderer (std::thread tiles) and CudaRenderer (one
// CUDA thread per pixel) implement it as thin backends over one host scene (RenderScene.h), with
// the same per-sample kernel (Integrators.h), the same accumulation (sum, sum of squares, count
// per pixel) and the same random streams, so their images are meant to agree within Monte Carlo
// noise; TestCudaRenderer checks that, but it has never run on a GPU in this project (it skips
// without a CUDA device), so the agreement is designed, not observed. Plain C++: no CUDA
// headers. Which implementation to create is RendererFactory.h. Host code.
#pragma once

#include "core/WorkCounters.h"
#include "mesh/DualMesh.h"
#include "render/RenderParams.h"
#include "render/RenderScene.h"
#include "sampling/TransferFunction.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace amrdm
{

/// Work totals since the last reset(): samples and the work counters (core/WorkCounters.h).
struct RenderStats
{
  std::uint64_t samples = 0;
#define AMRDM_STATS_COUNTER(name, doc) std::uint64_t name = 0;
  AMRDM_WORK_COUNTERS(AMRDM_STATS_COUNTER)
#undef AMRDM_STATS_COUNTER
  int passes = 0;
};

/// Work counters summed over the tiles of CPU passes (thread safe; TiledPass.h adds to them).
struct PassTotals
{
  std::atomic<std::uint64_t> samples{ 0 };
#define AMRDM_TOTALS_COUNTER(name, doc)                                                            \
  std::atomic<std::uint64_t> name{ 0 }; // NOLINT(bugprone-macro-parentheses)
  AMRDM_WORK_COUNTERS(AMRDM_TOTALS_COUNTER)
#undef AMRDM_TOTALS_COUNTER

  void clear()
  {
    this->samples = 0;
#define AMRDM_CLEAR_COUNTER(name, doc) this->name = 0;
    AMRDM_WORK_COUNTERS(AMRDM_CLEAR_COUNTER)
#undef AMRDM_CLEAR_COUNTER
  }
  /// As RenderStats, with `passes`.
  RenderStats stats(int passes) const
  {
    RenderStats s;
    s.samples = this->samples.load();
    addWorkCounters(s, *this);
    s.passes = passes;
    return s;
  }
};

/// Where a renderer runs. Auto = CUDA when this build has it and a device is present, else the
/// CPU (RendererFactory.h says which, once).
enum class RenderDevice : int
{
  Auto = 0,
  Cpu = 1,
  Cuda = 2
};

inline const char* renderDeviceName(RenderDevice d)
{
  return d == RenderDevice::Cpu ? "cpu" : (d == RenderDevice::Cuda ? "cuda" : "auto");
}

/// Parses "auto", "cpu" or "cuda"; false for anything else.
inline bool parseRenderDevice(const std::string& name, RenderDevice& out)
{
  for (RenderDevice d : { RenderDevice::Auto, RenderDevice::Cpu, RenderDevice::Cuda })
  {
    if (name == renderDeviceName(d))
    {
      out = d;
      return true;
    }
  }
  return false;
}

class Renderer
{
public:
  virtual ~Renderer() = default;

  /// RenderDevice::Cpu or RenderDevice::Cuda.
  virtual RenderDevice device() const = 0;
  /// The mesh to render (not owned; must outlive the renderer's use): RenderScene::setMesh.
  /// `majorantResolution` (<= 0: automatic) is what the majorant grid is first built at; a pass
  /// with another RenderParams::majorantResolution rebuilds only that grid.
  virtual void setMesh(const DualMesh* mesh,
    glm::ivec3 majorantResolution = glm::ivec3(0),
    int threads = 0) = 0;
  /// Copies the transfer function; recomputes majorants and culling masks only.
  virtual void setTransferFunction(const TransferFunction& tf, int threads = 0) = 0;
  /// Data-parallel rendering with a proxy (DistributionMode Proxy): `proxy` (not owned; the
  /// coarse mesh of the whole domain, same scene frame as the mesh) answers outside the box
  /// [lo, hi] (scene frame: the region this process draws) for the scattered and shadow rays
  /// of the integrators that scatter (IntegratorList.h; sampling/CompositeMedium.h). Null clears
  /// it.
  /// Call after setMesh(). Every renderer takes it through its RenderScene (SceneRenderer.h:
  /// CpuRenderer, CudaRenderer). Throws std::invalid_argument for an empty box with a proxy.
  virtual void setProxy(const DualMesh* proxy,
    const glm::vec3& lo,
    const glm::vec3& hi,
    int threads = 0) = 0;
  /// Clears the accumulation buffers and statistics.
  virtual void reset() = 0;
  /// Adds params.samplesPerPass samples to every pixel (see CpuRenderer.h for depthMaxT and
  /// minT: width*height floats, row-major from the bottom row). False when cancel() stopped it.
  virtual bool renderPass(const RenderParams& params,
    const float* depthMaxT = nullptr,
    const float* minT = nullptr) = 0;
  /// Asks the running pass to stop (thread safe); no effect when no pass runs
  /// (render/PassCancellation.h).
  virtual void cancel() = 0;
  /// Mean premultiplied RGBA per pixel (4 floats each).
  virtual std::vector<float> image() const = 0;
  /// Per-pixel variance of the mean, per channel (4 floats each): sample variance / count.
  virtual std::vector<float> varianceOfMean() const = 0;
  virtual RenderStats stats() const = 0;
  /// Host bytes of what the renderer derives from the mesh on top of it: the majorant grid
  /// (ranges, finest widths, majorants) and the culling ranges and masks. With the mesh's
  /// MemoryReport::total() it is the all-in memory of a rendered data set.
  virtual std::uint64_t accelerationBytes() const = 0;
  /// Device memory by category as JSON (CudaRenderer: GpuMemoryReport); empty on the CPU.
  virtual std::string deviceMemoryJson() const { return std::string(); }
};

/// Mean and variance of the mean of one pixel's accumulators (n samples), per channel: what
/// image() and varianceOfMean() return. Shared so both renderers report identically. The sums
/// are double (per sample and per pixel): a float running sum of n samples loses log2(n) bits.
inline glm::vec4 accumulatedMean(const glm::dvec4& sum, std::uint32_t n)
{
  return n > 0 ? glm::vec4(sum / double(n)) : glm::vec4(0.0f);
}
inline glm::vec4 accumulatedVarianceOfMean(const glm::dvec4& sum,
  const glm::dvec4& sumSq,
  std::uint32_t count)
{
  const double n = double(count);
  if (!(n > 1.0))
  {
    return glm::vec4(0.0f);
  }
  const glm::dvec4 m = sum / n;
  const glm::dvec4 var = glm::max(glm::dvec4(0.0), (sumSq / n - m * m) * (n / (n - 1.0)));
  return glm::vec4(var / n);
}

/// image() (sumSq null: the mean) or varianceOfMean() (the variance of the mean) from the
/// accumulators of n pixels, 4 floats per pixel.
inline std::vector<float> accumulatedImage(const glm::dvec4* sum,
  const glm::dvec4* sumSq,
  const std::uint32_t* count,
  std::size_t n)
{
  std::vector<float> out(n * 4, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::vec4 v = sumSq ? accumulatedVarianceOfMean(sum[i], sumSq[i], count[i])
                              : accumulatedMean(sum[i], count[i]);
    for (int c = 0; c < 4; ++c)
      out[4 * i + c] = v[c];
  }
  return out;
}

/// Bytes of accumulation buffers per pixel (double sum and sum of squares of RGBA, a count).
constexpr std::uint64_t kAccumulationBytesPerPixel = 2 * sizeof(glm::dvec4) + sizeof(std::uint32_t);

/// Throws std::length_error, before anything is allocated, when the accumulation buffers of a
/// width x height image need more than `availableBytes` (0 = unknown: no check).
inline void checkAccumulationMemory(int width, int height, std::uint64_t availableBytes)
{
  const std::uint64_t bytes =
    std::uint64_t(width) * std::uint64_t(height) * kAccumulationBytesPerPixel;
  if (availableBytes > 0 && bytes > availableBytes)
  {
    throw std::length_error(
      "a " + std::to_string(width) + " x " + std::to_string(height) + " image needs " +
      std::to_string(bytes >> 20) + " MiB of accumulation buffers (" +
      std::to_string(kAccumulationBytesPerPixel) + " bytes per pixel), but only " +
      std::to_string(availableBytes >> 20) + " MiB are available; expected a smaller image");
  }
}

} // namespace amrdm
