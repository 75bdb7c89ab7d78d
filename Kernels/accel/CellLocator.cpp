#include "accel/CellLocator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amrdm
{

namespace
{
/// Aim for about this many bins per block: small enough to scan, large enough to be selective.
constexpr double kBinsPerBlock = 8.0;
/// Never allocate more bins than this per level, whatever the spread of the boxes.
constexpr std::int64_t kMaxBinsPerLevel = std::int64_t(1) << 22;
} // namespace

CellLocator::CellLocator(const AmrHierarchy& amr)
  : Amr(amr)
{
  this->BlockOffset.assign(amr.blocks.size() + 1, 0);
  for (std::size_t b = 0; b < amr.blocks.size(); ++b)
  {
    this->BlockOffset[b + 1] = this->BlockOffset[b] + amr.blocks[b].numCells();
  }
  this->Levels.resize(static_cast<std::size_t>(amr.numLevels()));
  for (int level = 0; level < amr.numLevels(); ++level)
  {
    this->Width.push_back(amr.levelWidth(level));
    LevelGrid& grid = this->Levels[static_cast<std::size_t>(level)];
    glm::ivec3 lo(std::numeric_limits<int>::max()), hi(std::numeric_limits<int>::min());
    std::int64_t numBlocks = 0;
    for (const AmrBlock& block : amr.blocks)
    {
      if (block.level == level)
      {
        lo = glm::min(lo, block.lower);
        hi = glm::max(hi, block.lower + block.dims);
        ++numBlocks;
      }
    }
    if (numBlocks == 0)
    {
      continue;
    }
    const glm::dvec3 extent = glm::dvec3(hi - lo);
    const double volume = extent.x * extent.y * extent.z;
    const double targetBins =
      std::min<double>(kBinsPerBlock * static_cast<double>(numBlocks), double(kMaxBinsPerLevel));
    int binSize = std::max(1, static_cast<int>(std::ceil(std::cbrt(volume / targetBins))));
    glm::ivec3 bins;
    for (;;)
    {
      bins = (hi - lo + binSize - 1) / binSize;
      if (static_cast<std::int64_t>(bins.x) * bins.y * bins.z <= kMaxBinsPerLevel)
      {
        break;
      }
      binSize *= 2;
    }
    grid.lower = lo;
    grid.bins = bins;
    grid.binSize = binSize;
    const std::size_t numBins = static_cast<std::size_t>(bins.x) * bins.y * bins.z;
    std::vector<std::uint32_t> counts(numBins + 1, 0);
    auto forBins = [&](const AmrBlock& block, auto&& fn)
    {
      const glm::ivec3 b0 = (block.lower - lo) / binSize;
      const glm::ivec3 b1 = (block.lower + block.dims - 1 - lo) / binSize;
      for (int z = b0.z; z <= b1.z; ++z)
        for (int y = b0.y; y <= b1.y; ++y)
          for (int x = b0.x; x <= b1.x; ++x)
          {
            fn((static_cast<std::size_t>(z) * bins.y + y) * bins.x + x);
          }
    };
    for (const AmrBlock& block : amr.blocks)
    {
      if (block.level == level)
      {
        forBins(block, [&](std::size_t bin) { ++counts[bin + 1]; });
      }
    }
    for (std::size_t i = 0; i < numBins; ++i)
    {
      counts[i + 1] += counts[i];
    }
    grid.binStart = counts;
    grid.binBlocks.resize(counts[numBins]);
    for (std::uint32_t b = 0; b < amr.blocks.size(); ++b)
    {
      if (amr.blocks[b].level == level)
      {
        forBins(amr.blocks[b], [&](std::size_t bin) { grid.binBlocks[counts[bin]++] = b; });
      }
    }
  }
}

int CellLocator::findBlock(int level, const glm::ivec3& c) const
{
  const LevelGrid& grid = this->Levels[static_cast<std::size_t>(level)];
  if (grid.binStart.empty())
  {
    return -1;
  }
  const glm::ivec3 rel = c - grid.lower;
  if (rel.x < 0 || rel.y < 0 || rel.z < 0)
  {
    return -1;
  }
  const glm::ivec3 bin = rel / grid.binSize;
  if (bin.x >= grid.bins.x || bin.y >= grid.bins.y || bin.z >= grid.bins.z)
  {
    return -1;
  }
  const std::size_t id =
    (static_cast<std::size_t>(bin.z) * grid.bins.y + bin.y) * grid.bins.x + bin.x;
  for (std::uint32_t i = grid.binStart[id]; i < grid.binStart[id + 1]; ++i)
  {
    const std::uint32_t b = grid.binBlocks[i];
    if (this->Amr.blocks[b].contains(c))
    {
      return static_cast<int>(b);
    }
  }
  return -1;
}

int CellLocator::findBlock(int level, const glm::ivec3& c, BlockHint& hint) const
{
  for (const int b : hint.block)
  {
    if (b >= 0 && this->Amr.blocks[static_cast<std::size_t>(b)].level == level &&
        this->Amr.blocks[static_cast<std::size_t>(b)].contains(c))
    {
      return b;
    }
  }
  const int b = this->findBlock(level, c);
  if (b >= 0)
  {
    hint.block[1] = hint.block[0];
    hint.block[0] = b;
  }
  return b;
}

CellRef CellLocator::fromGlobalId(std::int64_t id) const
{
  const auto it = std::upper_bound(this->BlockOffset.begin(), this->BlockOffset.end(), id);
  CellRef ref;
  ref.kind = CellRef::Leaf;
  ref.block = static_cast<std::uint32_t>(it - this->BlockOffset.begin() - 1);
  ref.cell = id - this->BlockOffset[ref.block];
  ref.level = this->Amr.blocks[ref.block].level;
  return ref;
}

glm::dvec3 CellLocator::centre(const CellRef& ref) const
{
  const AmrBlock& block = this->Amr.blocks[ref.block];
  const std::int64_t nx = block.dims.x, ny = block.dims.y;
  const glm::dvec3 local(double(ref.cell % nx),
    double((ref.cell / nx) % ny),
    double(ref.cell / (nx * ny))); // NOLINT(bugprone-integer-division): the z index
  const double w = static_cast<double>(this->levelWidth(block.level));
  return (glm::dvec3(block.lower) + local + 0.5) * w;
}

float CellLocator::value(std::int64_t id) const
{
  const CellRef ref = this->fromGlobalId(id);
  return this->Amr.blocks[ref.block].values[static_cast<std::size_t>(ref.cell)];
}

CellRef CellLocator::locate(int level, const glm::ivec3& c, BlockHint* hint) const
{
  CellRef ref;
  glm::ivec3 idx = c;
  for (int l = level; l >= 0; --l)
  {
    if (l < level)
    {
      const int r = this->Amr.ratio[static_cast<std::size_t>(l + 1)];
      idx = glm::ivec3(floorDiv(idx.x, r), floorDiv(idx.y, r), floorDiv(idx.z, r));
    }
    const int b = hint ? this->findBlock(l, idx, *hint) : this->findBlock(l, idx);
    if (b < 0)
    {
      continue;
    }
    const AmrBlock& block = this->Amr.blocks[static_cast<std::size_t>(b)];
    const std::int64_t cell = block.cellIndex(idx);
    const std::uint8_t state = block.state[static_cast<std::size_t>(cell)];
    ref.level = l;
    ref.block = static_cast<std::uint32_t>(b);
    ref.cell = cell;
    if (state == CellLeaf)
    {
      ref.kind = CellRef::Leaf;
    }
    else if (state == CellRefined && l == level)
    {
      ref.kind = CellRef::Finer;
    }
    else
    {
      // Hidden, or a coarser cell claiming refinement where the finer level has no box.
      ref.kind = CellRef::Missing;
    }
    return ref;
  }
  return ref;
}

} // namespace amrdm
