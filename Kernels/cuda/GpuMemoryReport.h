// What the CUDA renderer reports about device memory (GpuMemoryReport, by category) and the
// exception it throws when an allocation does not fit (GpuOutOfMemory). Plain C++ (no CUDA
// headers).
#pragma once

#include <cstdint>
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

} // namespace amrdm
