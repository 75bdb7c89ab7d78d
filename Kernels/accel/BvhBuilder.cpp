// Binned-SAH BVH construction (host). Children of a node are stored next to each other, so an
// inner node needs one index. The build order is fixed, so the tree is deterministic, and the
// same for every thread count:
//  1. the top of the tree is split on the calling thread, each large node's binning and
//     partition spread over the threads in fixed chunks (merged in chunk order), until every
//     open range holds at most kSubtreePrims primitives (a fixed size, not a thread count);
//  2. those ranges' subtrees are built in parallel, each into its own node array;
//  3. the subtrees are appended in the order their ranges were opened.
#include "accel/Bvh.h"

#include "core/ParallelFor.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace amrdm
{

namespace
{
constexpr int kSahBins = 16;
/// Relative cost of a box test against a primitive test in the SAH.
constexpr float kTraversalCost = 0.5f;
/// Ranges of at most this many primitives become subtrees built in parallel.
constexpr std::uint32_t kSubtreePrims = 1u << 14;
/// Primitives per chunk when one node's binning or partition is spread over threads.
constexpr std::uint32_t kChunkPrims = 1u << 15;
// Subtrees are never wide, so step 2 never nests a parallel loop.
static_assert(kSubtreePrims <= kChunkPrims, "a subtree must fit in one chunk");

struct Box
{
  glm::vec3 lo{ std::numeric_limits<float>::max() };
  glm::vec3 hi{ -std::numeric_limits<float>::max() };
  void grow(const glm::vec3& a, const glm::vec3& b)
  {
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  void grow(const Box& o) { grow(o.lo, o.hi); }
  float area() const
  {
    if (lo.x > hi.x)
    {
      return 0.0f;
    }
    const glm::vec3 d = hi - lo;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

struct Task
{
  std::uint32_t node, begin, end;
  int depth;
};

/// What one pass over a range gathers: its bounds, its centroid bounds, and per axis the bins
/// of the centroids over `cbounds` (binning needs cbounds first: two passes).
struct RangeStats
{
  Box bounds, cbounds;
  Box binBox[3][kSahBins];
  std::uint32_t binCount[3][kSahBins] = {};
};

/// Builds the tree over `order` (a permutation of the primitives, partitioned in place).
class Builder
{
public:
  Builder(const std::vector<glm::vec3>& lo_,
    const std::vector<glm::vec3>& hi_,
    std::vector<std::uint32_t>& order_,
    int maxLeafSize_,
    int threads_)
    : lo(lo_)
    , hi(hi_)
    , order(order_)
    , maxLeafSize(static_cast<std::uint32_t>(std::max(1, maxLeafSize_)))
    , threads(threads_)
  {
    this->centroid.resize(order_.size());
    parallelFor((order_.size() + kChunkPrims - 1) / kChunkPrims,
      threads_,
      [&](std::size_t c)
      {
        const std::size_t end = std::min(order_.size(), (c + 1) * kChunkPrims);
        for (std::size_t i = c * kChunkPrims; i < end; ++i)
        {
          this->centroid[i] = 0.5f * (lo_[i] + hi_[i]);
        }
      });
  }

  /// Splits `task` (or makes it a leaf) into `nodes`; children go onto `stack`. Ranges larger
  /// than kChunkPrims are gathered and partitioned on all threads.
  void process(const Task& task, std::vector<BvhNode>& nodes, std::vector<Task>& stack, int& depth)
  {
    const std::uint32_t count = task.end - task.begin;
    const bool wide = count > kChunkPrims && this->threads != 1;
    RangeStats s;
    this->gather(task, s, wide);
    auto makeLeaf = [&]() { nodes[task.node] = { s.bounds.lo, task.begin, s.bounds.hi, count }; };
    // Turns the node into an inner node with children [begin, mid) and [mid, end).
    auto split = [&](std::uint32_t mid)
    {
      const std::uint32_t child = static_cast<std::uint32_t>(nodes.size());
      nodes.push_back({});
      nodes.push_back({});
      nodes[task.node] = { s.bounds.lo, child, s.bounds.hi, 0 };
      stack.push_back({ child + 1, mid, task.end, task.depth + 1 });
      stack.push_back({ child, task.begin, mid, task.depth + 1 });
    };
    depth = std::max(depth, task.depth);
    if (count <= this->maxLeafSize || task.depth >= kBvhMaxDepth - 1)
    {
      makeLeaf();
      return;
    }
    // Best binned SAH split over the three axes.
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!(s.cbounds.hi[axis] - s.cbounds.lo[axis] > 0.0f))
      {
        continue;
      }
      float rightArea[kSahBins];
      std::uint32_t rightCount[kSahBins];
      Box acc;
      std::uint32_t accCount = 0;
      for (int b = kSahBins - 1; b > 0; --b)
      {
        acc.grow(s.binBox[axis][b]);
        accCount += s.binCount[axis][b];
        rightArea[b] = acc.area();
        rightCount[b] = accCount;
      }
      acc = Box();
      accCount = 0;
      for (int b = 0; b < kSahBins - 1; ++b)
      {
        acc.grow(s.binBox[axis][b]);
        accCount += s.binCount[axis][b];
        if (accCount == 0 || rightCount[b + 1] == 0)
        {
          continue;
        }
        const float cost = acc.area() * accCount + rightArea[b + 1] * rightCount[b + 1];
        if (cost < bestCost)
        {
          bestCost = cost;
          bestAxis = axis;
          bestSplit = b + 1;
        }
      }
    }
    const float leafCost = s.bounds.area() * count;
    if (bestAxis < 0 || (count <= 2u * this->maxLeafSize &&
                          kTraversalCost * s.bounds.area() + bestCost >= leafCost))
    {
      if (bestAxis < 0 && count > this->maxLeafSize)
      {
        // All centroids coincide: split the list in half to bound leaf size.
        split(task.begin + count / 2);
        return;
      }
      makeLeaf();
      return;
    }
    split(this->partition(task, s.cbounds, bestAxis, bestSplit, wide));
  }

private:
  /// Bin of primitive p's centroid along `axis` over `cbounds` (scale = bins / extent).
  int bin(std::uint32_t p, int axis, const Box& cbounds, float scale) const
  {
    return std::min(
      kSahBins - 1, static_cast<int>((this->centroid[p][axis] - cbounds.lo[axis]) * scale));
  }

  static float binScale(const Box& cbounds, int axis)
  {
    return kSahBins / (cbounds.hi[axis] - cbounds.lo[axis]);
  }

  void boundsOf(std::uint32_t begin, std::uint32_t end, RangeStats& s) const
  {
    for (std::uint32_t i = begin; i < end; ++i)
    {
      const std::uint32_t p = this->order[i];
      s.bounds.grow(this->lo[p], this->hi[p]);
      s.cbounds.grow(this->centroid[p], this->centroid[p]);
    }
  }

  void binsOf(std::uint32_t begin, std::uint32_t end, const Box& cbounds, RangeStats& s) const
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!(cbounds.hi[axis] - cbounds.lo[axis] > 0.0f))
      {
        continue;
      }
      const float scale = binScale(cbounds, axis);
      for (std::uint32_t i = begin; i < end; ++i)
      {
        const std::uint32_t p = this->order[i];
        const int b = this->bin(p, axis, cbounds, scale);
        s.binBox[axis][b].grow(this->lo[p], this->hi[p]);
        ++s.binCount[axis][b];
      }
    }
  }

  /// Bounds, centroid bounds and bins of the task's range; when wide, in fixed chunks on all
  /// threads, merged in chunk order (min, max and counts: the same result as one pass).
  void gather(const Task& task, RangeStats& s, bool wide) const
  {
    const bool bins = task.end - task.begin > this->maxLeafSize;
    if (!wide)
    {
      this->boundsOf(task.begin, task.end, s);
      if (bins)
      {
        this->binsOf(task.begin, task.end, s.cbounds, s);
      }
      return;
    }
    const std::size_t chunks = (task.end - task.begin + kChunkPrims - 1) / kChunkPrims;
    auto range = [&](std::size_t c)
    {
      const std::uint32_t b = task.begin + static_cast<std::uint32_t>(c) * kChunkPrims;
      return std::make_pair(b, std::min(task.end, b + kChunkPrims));
    };
    std::vector<RangeStats> part(chunks);
    parallelFor(chunks,
      this->threads,
      [&](std::size_t c)
      {
        const auto r = range(c);
        this->boundsOf(r.first, r.second, part[c]);
      });
    for (const RangeStats& r : part)
    {
      s.bounds.grow(r.bounds);
      s.cbounds.grow(r.cbounds);
    }
    if (!bins)
    {
      return;
    }
    parallelFor(chunks,
      this->threads,
      [&](std::size_t c)
      {
        const auto r = range(c);
        this->binsOf(r.first, r.second, s.cbounds, part[c]);
      });
    for (const RangeStats& r : part)
    {
      for (int axis = 0; axis < 3; ++axis)
      {
        for (int b = 0; b < kSahBins; ++b)
        {
          s.binBox[axis][b].grow(r.binBox[axis][b]);
          s.binCount[axis][b] += r.binCount[axis][b];
        }
      }
    }
  }

  /// Stable partition of [begin, end) by bin < split; returns the first index of the right side.
  std::uint32_t partition(const Task& task, const Box& cbounds, int axis, int split, bool wide)
  {
    const float scale = binScale(cbounds, axis);
    auto left = [&](std::uint32_t p) { return this->bin(p, axis, cbounds, scale) < split; };
    if (!wide)
    {
      return static_cast<std::uint32_t>(
        std::stable_partition(
          this->order.begin() + task.begin, this->order.begin() + task.end, left) -
        this->order.begin());
    }
    const std::uint32_t count = task.end - task.begin;
    const std::size_t chunks = (count + kChunkPrims - 1) / kChunkPrims;
    auto chunkEnd = [&](std::size_t c)
    { return std::min(task.end, task.begin + static_cast<std::uint32_t>(c + 1) * kChunkPrims); };
    std::vector<std::uint32_t> lefts(chunks, 0);
    parallelFor(chunks,
      this->threads,
      [&](std::size_t c)
      {
        for (std::uint32_t i = task.begin + static_cast<std::uint32_t>(c) * kChunkPrims;
             i < chunkEnd(c);
             ++i)
        {
          lefts[c] += left(this->order[i]) ? 1u : 0u;
        }
      });
    std::vector<std::uint32_t> leftAt(chunks), rightAt(chunks);
    const std::uint32_t totalLeft = std::accumulate(lefts.begin(), lefts.end(), 0u);
    std::uint32_t l = 0, r = totalLeft;
    for (std::size_t c = 0; c < chunks; ++c)
    {
      leftAt[c] = l;
      rightAt[c] = r;
      l += lefts[c];
      r += static_cast<std::uint32_t>(chunkEnd(c) - task.begin - c * kChunkPrims) - lefts[c];
    }
    std::vector<std::uint32_t> out(count);
    parallelFor(chunks,
      this->threads,
      [&](std::size_t c)
      {
        std::uint32_t li = leftAt[c], ri = rightAt[c];
        for (std::uint32_t i = task.begin + static_cast<std::uint32_t>(c) * kChunkPrims;
             i < chunkEnd(c);
             ++i)
        {
          const std::uint32_t p = this->order[i];
          out[left(p) ? li++ : ri++] = p;
        }
      });
    std::copy(out.begin(), out.end(), this->order.begin() + task.begin);
    return task.begin + totalLeft;
  }

  const std::vector<glm::vec3>& lo;
  const std::vector<glm::vec3>& hi;
  std::vector<std::uint32_t>& order;
  std::vector<glm::vec3> centroid; ///< indexed by primitive
  const std::uint32_t maxLeafSize;
  const int threads;
};

/// A subtree built on its own: nodes[0] is the root of the range `task`.
struct Subtree
{
  Task task;
  std::vector<BvhNode> nodes;
  int depth = 0;
};
} // namespace

Bvh buildBvh(const std::vector<glm::vec3>& lo,
  const std::vector<glm::vec3>& hi,
  const std::vector<std::uint32_t>& refs,
  int maxLeafSize,
  int threads)
{
  if (lo.size() != hi.size() || lo.size() != refs.size())
  {
    throw std::invalid_argument("buildBvh: box and reference arrays differ in length (" +
                                std::to_string(lo.size()) + " lower corners, " +
                                std::to_string(hi.size()) + " upper corners, " +
                                std::to_string(refs.size()) + " references; expected equal)");
  }
  Bvh bvh;
  const std::uint32_t n = static_cast<std::uint32_t>(refs.size());
  if (n == 0)
  {
    return bvh;
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  Builder builder(lo, hi, order, maxLeafSize, threads);

  // 1. The top, on this thread; ranges of at most kSubtreePrims wait for step 2.
  bvh.nodes.reserve(2 * static_cast<std::size_t>(n) / std::max(1, maxLeafSize) + 1);
  bvh.nodes.push_back({});
  std::vector<Subtree> subtrees;
  std::vector<Task> stack{ { 0, 0, n, 1 } };
  while (!stack.empty())
  {
    const Task task = stack.back();
    stack.pop_back();
    if (task.end - task.begin <= kSubtreePrims)
    {
      subtrees.push_back({ task, {}, 0 });
      continue;
    }
    builder.process(task, bvh.nodes, stack, bvh.depth);
  }

  // 2. The subtrees, in parallel, each rooted at its own node 0.
  parallelFor(subtrees.size(),
    threads,
    [&](std::size_t i)
    {
      Subtree& sub = subtrees[i];
      sub.nodes.push_back({});
      std::vector<Task> local{ { 0, sub.task.begin, sub.task.end, sub.task.depth } };
      while (!local.empty())
      {
        const Task t = local.back();
        local.pop_back();
        builder.process(t, sub.nodes, local, sub.depth);
      }
    });

  // 3. Appended in order: the root takes its reserved slot, the rest follow at `base`.
  for (const Subtree& sub : subtrees)
  {
    const std::uint32_t base = static_cast<std::uint32_t>(bvh.nodes.size());
    auto place = [&](BvhNode node)
    {
      if (node.count == 0)
      {
        node.first = base + node.first - 1; // local children are >= 1
      }
      return node;
    };
    bvh.nodes[sub.task.node] = place(sub.nodes[0]);
    for (std::size_t k = 1; k < sub.nodes.size(); ++k)
    {
      bvh.nodes.push_back(place(sub.nodes[k]));
    }
    bvh.depth = std::max(bvh.depth, sub.depth);
  }
  bvh.prims.resize(n);
  for (std::uint32_t i = 0; i < n; ++i)
  {
    bvh.prims[i] = refs[order[i]];
  }
  bvh.nodes.shrink_to_fit();
  return bvh;
}

} // namespace amrdm
