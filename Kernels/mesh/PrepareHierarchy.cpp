#include "mesh/PrepareHierarchy.h"

#include "core/ParallelFor.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace amrdm
{
namespace
{
std::string where(std::size_t level, std::size_t id)
{
  return "level " + std::to_string(level) + " block " + std::to_string(id);
}

/// Per block, the range of the values the field uses: leaf cells' values, or their corners'.
std::pair<double, double> blockRange(const AmrBlock& block, bool points)
{
  std::pair<double, double> r(
    std::numeric_limits<double>::max(), -std::numeric_limits<double>::max());
  for (int z = 0; z < block.dims.z; ++z)
    for (int y = 0; y < block.dims.y; ++y)
      for (int x = 0; x < block.dims.x; ++x)
      {
        const glm::ivec3 c = block.lower + glm::ivec3(x, y, z);
        if (block.state[static_cast<std::size_t>(block.cellIndex(c))] != CellLeaf)
          continue;
        for (int k = 0; k < (points ? 8 : 1); ++k)
        {
          const float v = points ? block.values[static_cast<std::size_t>(
                                     block.pointIndex(c + glm::ivec3(k & 1, (k >> 1) & 1, k >> 2)))]
                                 : block.values[static_cast<std::size_t>(block.cellIndex(c))];
          r.first = std::min(r.first, double(v));
          r.second = std::max(r.second, double(v));
        }
      }
  return r;
}
} // namespace

LevelBoxes levelBoxesOf(const AmrHierarchy& h)
{
  LevelBoxes boxes(static_cast<std::size_t>(h.numLevels()));
  for (const AmrBlock& b : h.blocks)
  {
    if (b.level < 0 || b.level >= h.numLevels())
      continue; // validate() reports it
    CellBox box;
    box.lower = glm::i64vec3(b.lower);
    box.upper = glm::i64vec3(b.lower) + glm::i64vec3(b.dims) - glm::i64vec3(1);
    boxes[static_cast<std::size_t>(b.level)].push_back(box);
  }
  return boxes;
}

void checkNesting(const std::vector<int>& ratio, const LevelBoxes& boxes, bool aligned)
{
  for (std::size_t l = 1; l < boxes.size() && l < ratio.size(); ++l)
  {
    const std::int64_t r = ratio[l];
    const BoxIndex parents(boxes[l - 1]);
    for (std::size_t id = 0; id < boxes[l].size(); ++id)
    {
      glm::i64vec3 lo = boxes[l][id].lower, hi = boxes[l][id].upper;
      if (hi.x < lo.x || hi.y < lo.y || hi.z < lo.z)
        continue; // empty: reported with the block
      std::int64_t cells = 1;
      for (int d = 0; d < 3; ++d)
      {
        if (aligned && (((lo[d] % r) + r) % r != 0 || (((hi[d] + 1) % r) + r) % r != 0))
          throw std::invalid_argument(where(l, id) + "'s box covers cells " +
                                      std::to_string(lo[d]) + ".." + std::to_string(hi[d]) +
                                      " on axis " + std::to_string(d) +
                                      ", which is not aligned with level " + std::to_string(l - 1) +
                                      "'s cells; expected its first " +
                                      "cell and its end (last + 1) to be multiples of the " +
                                      "refinement ratio " + std::to_string(r));
        // Now the level l - 1 cells it refines (floor division: boxes may start below zero).
        lo[d] = (lo[d] >= 0 ? lo[d] : lo[d] - r + 1) / r;
        hi[d] = (hi[d] >= 0 ? hi[d] : hi[d] - r + 1) / r;
        cells *= hi[d] - lo[d] + 1;
      }
      CellBox coarse;
      coarse.lower = lo;
      coarse.upper = hi;
      std::int64_t covered = 0;
      parents.forEachOverlap(coarse,
        [&](std::size_t pid)
        {
          const CellBox& parent = parents.box(pid);
          std::int64_t overlap = 1;
          for (int d = 0; d < 3; ++d)
            overlap *= std::min(coarse.upper[d], parent.upper[d]) -
                       std::max(coarse.lower[d], parent.lower[d]) + 1;
          covered += overlap;
        });
      if (covered < cells)
        throw std::invalid_argument(
          where(l, id) + " is not properly nested: " + std::to_string(cells - covered) +
          " of the " + std::to_string(cells) + " level-" + std::to_string(l - 1) +
          " cells it refines lie outside level " + std::to_string(l - 1) +
          "'s boxes; expected every refined " + "box inside the coarser level's boxes");
    }
  }
}

void checkHierarchy(const AmrHierarchy& h, const LevelBoxes* metadata)
{
  h.validate();
  if (metadata)
    checkNesting(h.ratio, *metadata, true);
  else
    checkNesting(h.ratio, levelBoxesOf(h), false);
}

HierarchySummary prepareHierarchy(AmrHierarchy& h, int threads, const LevelBoxes* metadata)
{
  checkHierarchy(h, metadata);
  HierarchySummary s;
  s.nonFiniteValues = h.finalizeCellStates(threads);
  leafValueRange(h, threads, s.valueRange);
  return s;
}

void leafValueRange(const AmrHierarchy& h, int threads, double out[2])
{
  const bool points = h.association == FieldAssociation::Points;
  std::vector<std::pair<double, double>> range(h.blocks.size());
  parallelFor(
    h.blocks.size(), threads, [&](std::size_t b) { range[b] = blockRange(h.blocks[b], points); });
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const std::pair<double, double>& r : range)
  {
    lo = std::min(lo, r.first);
    hi = std::max(hi, r.second);
  }
  out[0] = lo <= hi ? lo : 0.0;
  out[1] = lo <= hi ? hi : 0.0;
}

} // namespace amrdm
