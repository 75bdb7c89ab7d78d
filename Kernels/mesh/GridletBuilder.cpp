#include "mesh/GridletBuilder.h"

#include "core/ParallelFor.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace amrdm
{

namespace
{
/// Frees each block's input once no gridlet still to be filled reads it (buildGridlets). A
/// gridlet of level L reads only level-L blocks, at z positions from its clamped lower z up; the
/// gridlets are ordered by level, then z, so a level-L block whose top z lies below the smallest
/// clamped lower z of the level's remaining gridlets is not read again.
class InputRelease
{
public:
  InputRelease(const AmrHierarchy& amr, const DualMesh& mesh, const BlockRelease& release)
    : amr_(amr)
    , release_(release)
    , byLevel_(static_cast<std::size_t>(amr.numLevels()))
    , next_(static_cast<std::size_t>(amr.numLevels()), 0)
    , levelBegin_(static_cast<std::size_t>(amr.numLevels()), 0)
    , levelEnd_(static_cast<std::size_t>(amr.numLevels()), 0)
    , minZ_(mesh.gridlets.size())
  {
    if (!release_)
    {
      return;
    }
    for (std::uint32_t b = 0; b < amr.blocks.size(); ++b)
    {
      byLevel_[static_cast<std::size_t>(amr.blocks[b].level)].push_back(b);
    }
    for (std::vector<std::uint32_t>& blocks : byLevel_)
    {
      std::sort(blocks.begin(),
        blocks.end(),
        [&](std::uint32_t a, std::uint32_t b) { return topZ(a) < topZ(b); });
    }
    const GridBox domain = amr.domainBox();
    // Suffix minimum, per level, of the gridlets' clamped lower z.
    for (std::size_t g = mesh.gridlets.size(); g-- > 0;)
    {
      const GridletHeader& h = mesh.gridlets[g];
      const int w = static_cast<int>(amr.levelWidth(h.level));
      const int z = glm::clamp(h.lower.z, domain.lower.z / w, domain.upper.z / w - 1);
      const bool sameLevel = g + 1 < mesh.gridlets.size() && mesh.gridlets[g + 1].level == h.level;
      minZ_[g] = sameLevel ? std::min(z, minZ_[g + 1]) : z;
      levelBegin_[static_cast<std::size_t>(h.level)] = g;
      std::size_t& end = levelEnd_[static_cast<std::size_t>(h.level)];
      end = std::max(end, g + 1);
    }
  }

  /// Releases the blocks no gridlet from index `done` on reads.
  void upTo(std::size_t done)
  {
    if (!release_)
    {
      return;
    }
    std::vector<std::uint32_t> freed;
    for (std::size_t l = 0; l < byLevel_.size(); ++l)
    {
      const int limit = levelEnd_[l] <= done ? std::numeric_limits<int>::max()
                                             : minZ_[std::max(done, levelBegin_[l])];
      const std::vector<std::uint32_t>& blocks = byLevel_[l];
      for (std::size_t& i = next_[l]; i < blocks.size() && topZ(blocks[i]) < limit; ++i)
      {
        freed.push_back(blocks[i]);
      }
    }
    if (!freed.empty())
    {
      release_(freed);
    }
  }

private:
  int topZ(std::uint32_t b) const
  {
    const AmrBlock& block = amr_.blocks[b];
    return block.lower.z + block.dims.z - 1;
  }

  const AmrHierarchy& amr_;
  const BlockRelease& release_;
  std::vector<std::vector<std::uint32_t>> byLevel_; ///< per level, blocks by top z
  std::vector<std::size_t> next_;                   ///< per level, first block not released
  std::vector<std::size_t> levelBegin_;             ///< per level, its first gridlet
  std::vector<std::size_t> levelEnd_;               ///< per level, one past its last gridlet
  std::vector<int> minZ_;                           ///< per gridlet, see the constructor
};
} // namespace

void buildGridlets(const AmrHierarchy& amr,
  const CellLocator& locator,
  const std::vector<GridletRange>& sorted,
  int G,
  int threads,
  DualMesh& mesh,
  const BlockRelease& releaseBlocks)
{
  const GridBox domain = amr.domainBox();
  mesh.gridlets.resize(sorted.size());
  std::uint64_t offset = 0;
  for (std::size_t g = 0; g < sorted.size(); ++g)
  {
    GridletHeader& h = mesh.gridlets[g];
    h.lower = sorted[g].lo;
    h.level = sorted[g].level;
    h.dims = sorted[g].hi - sorted[g].lo + 1;
    if (offset > std::numeric_limits<std::uint32_t>::max())
    {
      throw std::invalid_argument("gridlet scalars exceed 2^32 values; use fewer cells");
    }
    h.begin = static_cast<std::uint32_t>(offset);
    offset += gridletScalarCount(sorted[g]);
  }
  if (offset > std::numeric_limits<std::uint32_t>::max())
  {
    throw std::invalid_argument("gridlet scalars exceed 2^32 values; use fewer cells");
  }
  // Uninitialised, in huge pages (core/DefaultInitAllocator.h): every scalar is written below.
  mesh.gridletScalars.resize(offset);
  const auto fill = [&](std::size_t g)
  {
    const GridletHeader& h = mesh.gridlets[g];
    float* s = mesh.gridletScalars.data() + h.begin;
    int cached = -1;
    // A lattice position beyond a domain face is a ghost: the value of the level's cell at the
    // clamped position (mesh/BoundaryLayer.h), when that is a leaf of this level.
    const int w = static_cast<int>(amr.levelWidth(h.level));
    const glm::ivec3 first = domain.lower / w, last = domain.upper / w - glm::ivec3(1);
    const float nan = std::numeric_limits<float>::quiet_NaN(); // no leaf of this level here
    for (int z = 0; z <= h.dims.z; ++z)
      for (int y = 0; y <= h.dims.y; ++y)
      {
        const int cy = glm::clamp(h.lower.y + y, first.y, last.y);
        const int cz = glm::clamp(h.lower.z + z, first.z, last.z);
        // Along x the clamped position runs through one block after another: each stretch is
        // read with its cell index stepping by one (the clamp is monotone, so a block's
        // stretch is contiguous).
        for (int x = 0; x <= h.dims.x;)
        {
          const glm::ivec3 c(glm::clamp(h.lower.x + x, first.x, last.x), cy, cz);
          if (cached < 0 || !amr.blocks[static_cast<std::size_t>(cached)].contains(c))
          {
            cached = locator.findBlock(h.level, c);
            if (cached < 0)
            {
              *s++ = nan;
              ++x;
              continue;
            }
          }
          const AmrBlock& block = amr.blocks[static_cast<std::size_t>(cached)];
          const int blockLast = block.lower.x + block.dims.x - 1;
          // Last x whose clamped position is still in this block.
          const int xLast =
            blockLast >= last.x ? h.dims.x : std::min(h.dims.x, blockLast - h.lower.x);
          const std::int64_t cell0 = block.cellIndex(c);
          for (; x <= xLast; ++x, ++s)
          {
            const std::size_t cell =
              static_cast<std::size_t>(cell0 + (glm::clamp(h.lower.x + x, first.x, last.x) - c.x));
            *s = block.state[cell] == CellLeaf ? block.values[cell] : nan;
          }
        }
      }
  };
  // One z-slab of gridlets (same level, same block of G lattice positions in z) at a time, so
  // that the input blocks below it can be released while the scalars fill up.
  const std::vector<glm::ivec3> origin = gridletBlockOrigins(amr);
  const auto slab = [&](std::size_t g)
  {
    const GridletHeader& h = mesh.gridlets[g];
    return std::make_pair(
      h.level, floorDiv(h.lower.z - origin[static_cast<std::size_t>(h.level)].z, G));
  };
  InputRelease release(amr, mesh, releaseBlocks);
  release.upTo(0); // levels without gridlets
  for (std::size_t begin = 0; begin < mesh.gridlets.size();)
  {
    std::size_t end = begin + 1;
    if (releaseBlocks)
    {
      while (end < mesh.gridlets.size() && slab(end) == slab(begin))
      {
        ++end;
      }
    }
    else
    {
      end = mesh.gridlets.size(); // nothing to release: all gridlets in one loop
    }
    parallelFor(end - begin, threads, [&](std::size_t i) { fill(begin + i); });
    release.upTo(end);
    begin = end;
  }
}

} // namespace amrdm
