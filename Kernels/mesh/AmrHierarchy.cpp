#include "mesh/AmrHierarchy.h"

#include "core/ParallelFor.h"
#include "mesh/BoxIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace amrdm
{

std::int64_t AmrHierarchy::levelWidth(int level) const
{
  std::int64_t w = 1;
  for (int l = level + 1; l < this->numLevels(); ++l)
  {
    w *= this->ratio[static_cast<std::size_t>(l)];
  }
  return w;
}

namespace
{
std::string blockName(std::size_t b, const AmrBlock& block)
{
  return "block " + std::to_string(b) + " (level " + std::to_string(block.level) + ")";
}

std::string boxText(const glm::i64vec3& lo, const glm::i64vec3& hi)
{
  auto v = [](const glm::i64vec3& p)
  {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) +
           ")";
  };
  return v(lo) + " to " + v(hi);
}

/// An explicit domain must lie on level-0 cell faces and contain every block.
void validateDomain(const AmrHierarchy& amr)
{
  const GridBox& box = amr.domain;
  if (box.lower == glm::ivec3(0) && box.upper == glm::ivec3(0))
  {
    return; // unset: the default domain
  }
  const glm::i64vec3 lo(box.lower), hi(box.upper);
  if (box.empty())
  {
    throw std::invalid_argument("the domain box " + boxText(lo, hi) +
                                " is empty; expected lower < upper on every axis (or all zero for "
                                "the default, the blocks' bounding box)");
  }
  const std::int64_t w0 = amr.levelWidth(0);
  for (int d = 0; d < 3; ++d)
  {
    if (lo[d] % w0 != 0 || hi[d] % w0 != 0)
    {
      throw std::invalid_argument("the domain box " + boxText(lo, hi) +
                                  " does not lie on level-0 cell faces; expected multiples of " +
                                  std::to_string(w0) + " finest cells on every axis");
    }
  }
  for (std::size_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    const std::int64_t w = amr.levelWidth(block.level);
    const glm::i64vec3 a = glm::i64vec3(block.lower) * w;
    const glm::i64vec3 c = (glm::i64vec3(block.lower) + glm::i64vec3(block.dims)) * w;
    if (glm::any(glm::lessThan(a, lo)) || glm::any(glm::greaterThan(c, hi)))
    {
      throw std::invalid_argument(blockName(b, block) + " spans finest cells " + boxText(a, c) +
                                  ", outside the domain box " + boxText(lo, hi) +
                                  "; expected every block inside the domain");
    }
  }
}
} // namespace

void AmrHierarchy::validate() const
{
  if (this->ratio.empty())
  {
    throw std::invalid_argument("AMR hierarchy has no levels; expected at least one level");
  }
  for (int l = 1; l < this->numLevels(); ++l)
  {
    if (this->ratio[static_cast<std::size_t>(l)] < 2)
    {
      throw std::invalid_argument("refinement ratio from level " + std::to_string(l - 1) +
                                  " to level " + std::to_string(l) + " is " +
                                  std::to_string(this->ratio[static_cast<std::size_t>(l)]) +
                                  "; expected an integer >= 2");
    }
  }
  // Total refinement (checked level by level, before levelWidth() could overflow).
  std::int64_t width = 1;
  for (int l = this->numLevels() - 1; l > 0; --l)
  {
    width *= this->ratio[static_cast<std::size_t>(l)];
    if (width > kMaxGridCoordinate || this->ratio[static_cast<std::size_t>(l)] > kMaxGridCoordinate)
    {
      throw std::invalid_argument(
        "a level-" + std::to_string(l - 1) +
        " cell spans more than 2^30 finest cells; expected a total refinement of at most 2^30 "
        "(grid coordinates are integers within +-2^30 finest cells)");
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    if (!(this->finestSpacing[d] > 0.0) || !std::isfinite(this->finestSpacing[d]))
    {
      throw std::invalid_argument("finest-level spacing must be positive and finite on every axis");
    }
  }
  std::vector<std::vector<std::size_t>> perLevel(this->ratio.size());
  for (std::size_t b = 0; b < this->blocks.size(); ++b)
  {
    const AmrBlock& block = this->blocks[b];
    if (block.level < 0 || block.level >= this->numLevels())
    {
      throw std::invalid_argument(blockName(b, block) + " is on a level outside [0, " +
                                  std::to_string(this->numLevels() - 1) + "]");
    }
    if (block.dims.x <= 0 || block.dims.y <= 0 || block.dims.z <= 0)
    {
      throw std::invalid_argument(
        blockName(b, block) + " has empty dimensions " + std::to_string(block.dims.x) + "x" +
        std::to_string(block.dims.y) + "x" + std::to_string(block.dims.z) +
        "; expected at least one cell per axis");
    }
    {
      const std::int64_t w = this->levelWidth(block.level);
      for (int d = 0; d < 3; ++d)
      {
        const std::int64_t lo = std::int64_t(block.lower[d]) * w;
        const std::int64_t hi = (std::int64_t(block.lower[d]) + block.dims[d]) * w;
        if (lo < -kMaxGridCoordinate || hi > kMaxGridCoordinate)
        {
          throw std::invalid_argument(
            blockName(b, block) + " spans finest-level cells " + std::to_string(lo) + " to " +
            std::to_string(hi) + " on axis " + std::to_string(d) +
            "; expected grid coordinates within +-2^30 finest cells (fewer levels, or a smaller "
            "domain)");
        }
      }
    }
    const bool points = this->association == FieldAssociation::Points;
    const std::int64_t expected = points ? block.numPoints() : block.numCells();
    if (static_cast<std::int64_t>(block.values.size()) != expected)
    {
      throw std::invalid_argument(blockName(b, block) + " has " +
                                  std::to_string(block.values.size()) +
                                  " values; expected one per " + (points ? "vertex" : "cell") +
                                  " (" + std::to_string(expected) + ")");
    }
    if (!block.state.empty() && static_cast<std::int64_t>(block.state.size()) != block.numCells())
    {
      throw std::invalid_argument(
        blockName(b, block) + " has " + std::to_string(block.state.size()) +
        " cell states; expected one per cell (" + std::to_string(block.numCells()) + ") or none");
    }
    perLevel[static_cast<std::size_t>(block.level)].push_back(b);
  }
  validateDomain(*this);
  // Overlap on one level, through an index of that level's boxes.
  for (const auto& ids : perLevel)
  {
    std::vector<CellBox> boxes(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      const AmrBlock& block = this->blocks[ids[i]];
      boxes[i].lower = glm::i64vec3(block.lower);
      boxes[i].upper = glm::i64vec3(block.lower) + glm::i64vec3(block.dims) - std::int64_t(1);
    }
    const BoxIndex index(boxes);
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      index.forEachOverlap(boxes[i],
        [&](std::size_t j)
        {
          if (j > i)
          {
            throw std::invalid_argument(blockName(ids[i], this->blocks[ids[i]]) + " and " +
                                        blockName(ids[j], this->blocks[ids[j]]) +
                                        " overlap; expected the boxes of one level to be disjoint");
          }
        });
    }
  }
}

GridBox AmrHierarchy::domainBox() const
{
  if (!this->domain.empty())
  {
    return this->domain;
  }
  GridBox box;
  if (this->blocks.empty() || this->ratio.empty())
  {
    return box;
  }
  const std::int64_t w0 = this->levelWidth(0);
  glm::i64vec3 lo(std::numeric_limits<std::int64_t>::max());
  glm::i64vec3 hi(std::numeric_limits<std::int64_t>::min());
  for (const AmrBlock& block : this->blocks)
  {
    const std::int64_t w = this->levelWidth(block.level);
    for (int d = 0; d < 3; ++d)
    {
      const std::int64_t a = std::int64_t(block.lower[d]) * w;
      const std::int64_t b = (std::int64_t(block.lower[d]) + block.dims[d]) * w;
      lo[d] = std::min(lo[d], (a >= 0 ? a / w0 : -((-a + w0 - 1) / w0)) * w0);
      hi[d] = std::max(hi[d], (b >= 0 ? (b + w0 - 1) / w0 : -(-b / w0)) * w0);
    }
  }
  box.lower = glm::ivec3(lo);
  box.upper = glm::ivec3(hi);
  return box;
}

namespace
{
/// The boxes of level `fine`'s blocks in level `fine - 1` cells (a coarse cell is touched when
/// any of its fine cells is), indexed; entry i is the i-th block of that level.
BoxIndex coarsenedBoxes(const AmrHierarchy& amr, int fine)
{
  const int r = amr.ratio[static_cast<std::size_t>(fine)];
  std::vector<CellBox> boxes;
  for (const AmrBlock& block : amr.blocks)
  {
    if (block.level != fine)
    {
      continue;
    }
    CellBox box;
    for (int d = 0; d < 3; ++d)
    {
      box.lower[d] = floorDiv(block.lower[d], r);
      box.upper[d] = floorDiv(block.lower[d] + block.dims[d] - 1, r);
    }
    boxes.push_back(box);
  }
  return BoxIndex(std::move(boxes));
}

/// Marks the cells of `block` that a block of the next finer level covers as CellRefined;
/// `finer` holds that level's boxes in this level's cells (coarsenedBoxes()).
void markRefined(const BoxIndex& finer, AmrBlock& block)
{
  CellBox self;
  for (int d = 0; d < 3; ++d)
  {
    self.lower[d] = block.lower[d];
    self.upper[d] = std::int64_t(block.lower[d]) + block.dims[d] - 1;
  }
  finer.forEachOverlap(self,
    [&](std::size_t i)
    {
      const CellBox& fine = finer.box(i);
      const glm::ivec3 lo(glm::max(fine.lower, self.lower));
      const glm::ivec3 hi(glm::min(fine.upper, self.upper));
      for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
          for (int x = lo.x; x <= hi.x; ++x)
          {
            block.state[static_cast<std::size_t>(block.cellIndex({ x, y, z }))] = CellRefined;
          }
    });
}

/// Vertex-centred data: every cell with a non-finite corner becomes CellHidden. Returns the
/// number of non-finite vertex values.
std::int64_t hideCellsAtNonFiniteVertices(AmrBlock& block)
{
  std::int64_t count = 0;
  for (int z = 0; z <= block.dims.z; ++z)
    for (int y = 0; y <= block.dims.y; ++y)
      for (int x = 0; x <= block.dims.x; ++x)
      {
        const glm::ivec3 v = block.lower + glm::ivec3(x, y, z);
        if (std::isfinite(block.values[static_cast<std::size_t>(block.pointIndex(v))]))
        {
          continue;
        }
        ++count;
        for (int k = 0; k < 8; ++k) // the up to 8 cells around the vertex
        {
          const glm::ivec3 c = v - glm::ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
          if (block.contains(c))
          {
            block.state[static_cast<std::size_t>(block.cellIndex(c))] = CellHidden;
          }
        }
      }
  return count;
}
} // namespace

std::int64_t AmrHierarchy::finalizeCellStates(int threads)
{
  std::vector<std::int64_t> nonFinite(this->blocks.size(), 0);
  // Per level with stateless blocks below it, the next finer level's boxes, indexed.
  std::vector<BoxIndex> finer;
  for (int l = 0; l + 1 < this->numLevels(); ++l)
  {
    const bool needed = std::any_of(this->blocks.begin(),
      this->blocks.end(),
      [&](const AmrBlock& b) { return b.level == l && b.state.empty(); });
    finer.push_back(needed ? coarsenedBoxes(*this, l + 1) : BoxIndex({}));
  }
  parallelFor(this->blocks.size(),
    threads,
    [&](std::size_t b)
    {
      AmrBlock& block = this->blocks[b];
      if (block.state.empty())
      {
        // Coverage by the next finer level, for blocks that came without a ghost array.
        block.state.assign(static_cast<std::size_t>(block.numCells()), CellLeaf);
        if (block.level + 1 < this->numLevels())
        {
          markRefined(finer[static_cast<std::size_t>(block.level)], block);
        }
      }
      if (this->association == FieldAssociation::Points)
      {
        nonFinite[b] = hideCellsAtNonFiniteVertices(block);
        return;
      }
      for (std::size_t i = 0; i < block.values.size(); ++i)
      {
        if (!std::isfinite(block.values[i]))
        {
          nonFinite[b] += block.state[i] == CellLeaf ? 1 : 0;
          block.state[i] = CellHidden;
        }
      }
    });
  std::int64_t total = 0;
  for (const std::int64_t n : nonFinite)
  {
    total += n;
  }
  return total;
}

std::int64_t AmrHierarchy::numLeafCells() const
{
  std::int64_t n = 0;
  for (const AmrBlock& block : this->blocks)
  {
    if (block.state.empty())
    {
      n += block.numCells();
      continue;
    }
    n += std::count(block.state.begin(), block.state.end(), CellLeaf);
  }
  return n;
}

} // namespace amrdm
