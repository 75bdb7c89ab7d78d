// See DomainPartition.h.
#include "mesh/DomainPartition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace amrdm
{
namespace
{

/// Leaf-cell weight of one cell of `level`: a level-0 cell is a leaf (1); a finer cell adds
/// itself and turns 1/r^3 of its parent from leaf to refined.
double cellWeight(const AmrHierarchy& amr, int level)
{
  if (level == 0)
  {
    return 1.0;
  }
  const double r = static_cast<double>(amr.ratio[static_cast<std::size_t>(level)]);
  return 1.0 - 1.0 / (r * r * r);
}

/// Weight of each level-0 slab of `box` along `axis` (size box.dims()[axis]).
std::vector<double> slabWeights(const AmrHierarchy& amr, const PartitionBox& box, int axis)
{
  const int extent = box.dims()[axis];
  std::vector<double> w(static_cast<std::size_t>(extent), 0.0);
  const std::int64_t w0 = amr.levelWidth(0);
  for (const AmrBlock& b : amr.blocks)
  {
    const std::int64_t wl = amr.levelWidth(b.level);
    const std::int64_t s = w0 / wl; // level-L cells per level-0 cell
    // Overlap of the block with the box, in level-L cells, per axis.
    glm::i64vec3 lo, hi;
    bool empty = false;
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::max<std::int64_t>(b.lower[d], std::int64_t(box.lower[d]) * s);
      hi[d] = std::min<std::int64_t>(
        std::int64_t(b.lower[d]) + b.dims[d], std::int64_t(box.upper[d]) * s);
      empty = empty || hi[d] <= lo[d];
    }
    if (empty)
    {
      continue;
    }
    double area = cellWeight(amr, b.level);
    for (int d = 0; d < 3; ++d)
    {
      area *= d == axis ? 1.0 : static_cast<double>(hi[d] - lo[d]);
    }
    for (std::int64_t c = lo[axis]; c < hi[axis];)
    {
      // Level-0 slab of cell c and the run of level-L cells in it.
      const std::int64_t slab = (c >= 0 ? c / s : -((-c + s - 1) / s));
      const std::int64_t end = std::min(hi[axis], (slab + 1) * s);
      w[static_cast<std::size_t>(slab - box.lower[axis])] += area * static_cast<double>(end - c);
      c = end;
    }
  }
  return w;
}

void bisect(const AmrHierarchy& amr,
  const PartitionBox& box,
  int first,
  int count,
  DomainPartition& out)
{
  if (count == 1)
  {
    out.regions[static_cast<std::size_t>(first)] = box;
    double total = 0.0;
    for (double v : slabWeights(amr, box, 0))
    {
      total += v;
    }
    out.leafCells[static_cast<std::size_t>(first)] = total;
    return;
  }
  const int nLeft = count / 2, nRight = count - nLeft;
  const glm::ivec3 dims = box.dims();
  int axes[3] = { 0, 1, 2 };
  std::stable_sort(axes, axes + 3, [&](int a, int b) { return dims[a] > dims[b]; });
  for (int axis : axes)
  {
    const int extent = dims[axis];
    const std::int64_t area = box.numCells() / extent;
    std::vector<double> w = slabWeights(amr, box, axis);
    double total = 0.0;
    for (double v : w)
    {
      total += v;
    }
    if (!(total > 0.0))
    {
      // No leaf cell in this box (no block reaches it): balance by level-0 cells instead.
      std::fill(w.begin(), w.end(), static_cast<double>(area));
      total = static_cast<double>(area) * extent;
    }
    const double target = total * nLeft / count;
    int best = -1;
    double bestError = std::numeric_limits<double>::infinity(), cum = 0.0;
    for (int s = 1; s < extent; ++s)
    {
      cum += w[static_cast<std::size_t>(s - 1)];
      if (std::int64_t(s) * area < nLeft || std::int64_t(extent - s) * area < nRight)
      {
        continue; // each region needs at least one level-0 cell
      }
      const double error = std::abs(cum - target);
      if (error < bestError)
      {
        bestError = error;
        best = s;
      }
    }
    if (best < 0)
    {
      continue;
    }
    PartitionBox left = box, right = box;
    left.upper[axis] = box.lower[axis] + best;
    right.lower[axis] = left.upper[axis];
    bisect(amr, left, first, nLeft, out);
    bisect(amr, right, first + nLeft, nRight, out);
    return;
  }
  throw std::invalid_argument("partitionDomain: a box of " + std::to_string(box.numCells()) +
                              " level-0 cells cannot be cut on level-0 faces into " +
                              std::to_string(count) +
                              " non-empty regions; expected fewer regions than level-0 cells");
}

} // namespace

void DomainPartition::gridBox(const AmrHierarchy& amr,
  int region,
  glm::dvec3& lo,
  glm::dvec3& hi) const
{
  const double w0 = static_cast<double>(amr.levelWidth(0));
  const PartitionBox& b = this->regions.at(static_cast<std::size_t>(region));
  lo = glm::dvec3(b.lower) * w0;
  hi = glm::dvec3(b.upper) * w0;
}

DomainPartition partitionDomain(const AmrHierarchy& amr, int numRegions)
{
  if (numRegions < 1)
  {
    throw std::invalid_argument(
      "partitionDomain: " + std::to_string(numRegions) + " regions requested; expected at least 1");
  }
  if (amr.numLevels() < 1)
  {
    throw std::invalid_argument(
      "partitionDomain: the hierarchy has no levels; expected at least one");
  }
  DomainPartition out;
  bool any = false;
  for (const AmrBlock& b : amr.blocks)
  {
    if (b.level != 0)
    {
      continue;
    }
    const glm::ivec3 upper = b.lower + b.dims;
    out.domain.lower = any ? glm::min(out.domain.lower, b.lower) : b.lower;
    out.domain.upper = any ? glm::max(out.domain.upper, upper) : upper;
    any = true;
  }
  if (!any || out.domain.numCells() <= 0)
  {
    throw std::invalid_argument("partitionDomain: the hierarchy has no level-0 block; expected the "
                                "coarsest level to define the domain");
  }
  if (out.domain.numCells() < numRegions)
  {
    throw std::invalid_argument("partitionDomain: " + std::to_string(numRegions) +
                                " regions requested but the domain has only " +
                                std::to_string(out.domain.numCells()) +
                                " level-0 cells; expected at most one region per level-0 cell");
  }
  out.regions.resize(static_cast<std::size_t>(numRegions));
  out.leafCells.resize(static_cast<std::size_t>(numRegions));
  bisect(amr, out.domain, 0, numRegions, out);
  return out;
}

void regionCellRange(const AmrHierarchy& amr,
  const PartitionBox& region,
  int level,
  glm::ivec3& lower,
  glm::ivec3& upper)
{
  const int s = static_cast<int>(amr.levelWidth(0) / amr.levelWidth(level));
  // One layer of level-L cells around the region (faces, edges and corners).
  lower = region.lower * s - 1;
  upper = region.upper * s + 1;
}

AmrHierarchy regionHierarchy(const AmrHierarchy& amr, const PartitionBox& region)
{
  const bool needStates = std::any_of(
    amr.blocks.begin(), amr.blocks.end(), [](const AmrBlock& b) { return b.state.empty(); });
  AmrHierarchy finalized;
  if (needStates)
  {
    finalized = amr;
    finalized.finalizeCellStates();
  }
  const AmrHierarchy& global = needStates ? finalized : amr;
  AmrHierarchy out;
  out.ratio = global.ratio;
  out.sceneOrigin = global.sceneOrigin;
  out.origin = global.origin;
  out.finestSpacing = global.finestSpacing;
  out.domain = global.domainBox(); // the region's cut faces are not domain faces: no ghosts there
  for (std::size_t i = 0; i < global.blocks.size(); ++i)
  {
    const AmrBlock& b = global.blocks[i];
    glm::ivec3 lo, hi;
    regionCellRange(global, region, b.level, lo, hi);
    lo = glm::max(lo, b.lower);
    hi = glm::min(hi, b.lower + b.dims);
    if (hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z)
    {
      continue;
    }
    if (static_cast<std::int64_t>(b.values.size()) != b.numCells())
    {
      throw std::invalid_argument(
        "regionHierarchy: block " + std::to_string(i) + " (level " + std::to_string(b.level) +
        ") reaches the region's ghost band but holds " + std::to_string(b.values.size()) +
        " values; expected one per cell (" + std::to_string(b.numCells()) +
        "): move its data to this rank first");
    }
    AmrBlock c;
    c.level = b.level;
    c.lower = lo;
    c.dims = hi - lo;
    c.values.reserve(static_cast<std::size_t>(c.numCells()));
    c.state.reserve(static_cast<std::size_t>(c.numCells()));
    for (int z = lo.z; z < hi.z; ++z)
      for (int y = lo.y; y < hi.y; ++y)
        for (int x = lo.x; x < hi.x; ++x)
        {
          const std::size_t k = static_cast<std::size_t>(b.cellIndex({ x, y, z }));
          c.values.push_back(b.values[k]);
          c.state.push_back(b.state[k]);
        }
    out.blocks.push_back(std::move(c));
  }
  return out;
}

} // namespace amrdm
