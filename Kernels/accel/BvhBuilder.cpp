// Binned-SAH BVH construction (host). Children of a node are stored next to each other, so an
// inner node needs one index. The build order is fixed, so the tree is deterministic, and the
// same for every thread count:
//  1. the top of the tree is split on the calling thread, each large node's binning and
//     partition spread over the threads in fixed chunks (merged in chunk order), until every
//     open range holds at most kSubtreePrims primitives (a fixed size, not a thread count);
//  2. those ranges' subtrees are built in parallel, each into its own node array;
//  3. the subtrees are appended in the order their ranges were opened.
// The primitives' boxes are permuted in place (stable partitions: the order, and so the tree,
// is that of partitioning an index array), so every pass reads them in sequence. A partition
// also gathers both sides' bounds and centroid bounds, so a node's own pass only bins.
#include "accel/BvhBuilder.h"
#include "accel/SahBins.h"

#include "core/ParallelFor.h"
#include "core/ReleaseMemory.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace amrdm
{

namespace
{
using namespace sah;

/// Relative cost of a box test against a primitive test in the SAH.
constexpr float kTraversalCost = 0.5f;
/// Ranges of at most this many primitives become subtrees built in parallel.
constexpr std::uint32_t kSubtreePrims = 1u << 14;
// Subtrees are never wide, so step 2 never nests a parallel loop.
static_assert(kSubtreePrims <= kBvhChunkPrims, "a subtree must fit in one chunk");

struct Task
{
  std::uint32_t node, begin, end;
  int depth;
  RangeBounds b;
};

/// Builds the tree over `prims` (permuted in place).
class Builder
{
public:
  Builder(DefaultInitVector<BvhPrimBox>& prims_, int maxLeafSize_, int threads_)
    : prims(prims_)
    , maxLeafSize(static_cast<std::uint32_t>(std::max(1, maxLeafSize_)))
    , threads(threads_)
    , workerScratch(static_cast<std::size_t>(resolveThreadCount(threads_)))
  {
  }

  /// Bounds of [begin, end): in fixed chunks on all threads when wide.
  RangeBounds boundsOf(std::uint32_t begin, std::uint32_t end) const
  {
    auto pass = [&](std::uint32_t b, std::uint32_t e)
    {
      RangeBounds r;
      for (std::uint32_t i = b; i < e; ++i)
      {
        r.grow(this->prims[i], centroidOf(this->prims[i]));
      }
      return r;
    };
    if (!this->wide(end - begin))
    {
      return pass(begin, end);
    }
    std::vector<RangeBounds> part(chunks(begin, end));
    parallelFor(part.size(),
      this->threads,
      [&](std::size_t c) { part[c] = pass(chunkBegin(begin, c), chunkEnd(begin, end, c)); });
    RangeBounds r;
    for (const RangeBounds& p : part)
    {
      r.grow(p);
    }
    return r;
  }

  /// Splits `task` (or makes it a leaf) into `nodes`; children go onto `stack`. Ranges larger
  /// than kBvhChunkPrims are binned and partitioned on all threads. `scratch`: the partition's
  /// right side, reused from node to node.
  void process(const Task& task,
    DefaultInitVector<BvhNode>& nodes,
    std::vector<Task>& stack,
    int& depth,
    DefaultInitVector<BvhPrimBox>& scratch)
  {
    const std::uint32_t count = task.end - task.begin;
    const Box& bounds = task.b.bounds;
    auto makeLeaf = [&]() { nodes[task.node] = { bounds.lo, task.begin, bounds.hi, count }; };
    // Turns the node into an inner node with children [begin, mid) and [mid, end).
    auto split = [&](std::uint32_t mid, const RangeBounds& left, const RangeBounds& right)
    {
      const std::uint32_t child = static_cast<std::uint32_t>(nodes.size());
      nodes.push_back({});
      nodes.push_back({});
      nodes[task.node] = { bounds.lo, child, bounds.hi, 0 };
      stack.push_back({ child + 1, mid, task.end, task.depth + 1, right });
      stack.push_back({ child, task.begin, mid, task.depth + 1, left });
    };
    depth = std::max(depth, task.depth);
    if (count <= this->maxLeafSize || task.depth >= kBvhMaxDepth - 1)
    {
      makeLeaf();
      return;
    }
    const BinMap map(task.b.cbounds);
    const Bins bins = this->binsOf(task, map);
    // Best binned SAH split over the three axes.
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      if (!map.live[axis])
      {
        continue;
      }
      float rightArea[kSahBins];
      std::uint32_t rightCount[kSahBins];
      Box acc;
      std::uint32_t accCount = 0;
      for (int b = kSahBins - 1; b > 0; --b)
      {
        acc.grow(bins.box[axis][b]);
        accCount += bins.count[axis][b];
        rightArea[b] = acc.area();
        rightCount[b] = accCount;
      }
      acc = Box();
      accCount = 0;
      for (int b = 0; b < kSahBins - 1; ++b)
      {
        acc.grow(bins.box[axis][b]);
        accCount += bins.count[axis][b];
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
    const float leafCost = bounds.area() * count;
    if (bestAxis < 0 ||
        (count <= 2u * this->maxLeafSize && kTraversalCost * bounds.area() + bestCost >= leafCost))
    {
      if (bestAxis < 0 && count > this->maxLeafSize)
      {
        // All centroids coincide: split the list in half to bound leaf size.
        const std::uint32_t mid = task.begin + count / 2;
        split(mid, this->boundsOf(task.begin, mid), this->boundsOf(mid, task.end));
        return;
      }
      makeLeaf();
      return;
    }
    RangeBounds left, right;
    const std::uint32_t mid = this->partition(task, map, bestAxis, bestSplit, left, right, scratch);
    split(mid, left, right);
  }

private:
  bool wide(std::uint32_t count) const { return count > kBvhChunkPrims && this->threads != 1; }
  static std::size_t chunks(std::uint32_t begin, std::uint32_t end)
  {
    return (end - begin + kBvhChunkPrims - 1) / kBvhChunkPrims;
  }
  static std::uint32_t chunkBegin(std::uint32_t begin, std::size_t c)
  {
    return begin + static_cast<std::uint32_t>(c) * kBvhChunkPrims;
  }
  static std::uint32_t chunkEnd(std::uint32_t begin, std::uint32_t end, std::size_t c)
  {
    return std::min(end, chunkBegin(begin, c + 1));
  }

  /// The bins of the task's range, all three axes in one pass; in chunks on all threads when
  /// wide, merged in chunk order (min, max and counts: the same result as one pass).
  Bins binsOf(const Task& task, const BinMap& map) const
  {
    auto pass = [&](std::uint32_t b, std::uint32_t e, Bins& s)
    {
      for (std::uint32_t i = b; i < e; ++i)
      {
        const BvhPrimBox& p = this->prims[i];
        const glm::vec3 c = centroidOf(p);
        for (int axis = 0; axis < 3; ++axis)
        {
          if (map.live[axis])
          {
            const int k = map.bin(c, axis);
            s.box[axis][k].grow(p.lo, p.hi);
            ++s.count[axis][k];
          }
        }
      }
    };
    Bins s;
    if (!this->wide(task.end - task.begin))
    {
      pass(task.begin, task.end, s);
      return s;
    }
    std::vector<Bins> part(chunks(task.begin, task.end));
    parallelFor(part.size(),
      this->threads,
      [&](std::size_t c)
      { pass(chunkBegin(task.begin, c), chunkEnd(task.begin, task.end, c), part[c]); });
    for (const Bins& p : part)
    {
      s.grow(p);
    }
    return s;
  }

  /// Stable partition of [begin, end) by bin < split; returns the first index of the right
  /// side, and gives each side's bounds. The left side moves down in place (never past the
  /// element being read), the right side waits in `scratch` and follows it. Wide: each chunk
  /// is partitioned so on its own thread, then rotations put the chunks' sides in order (every
  /// left side, then every right side, each in chunk order; pairwise, in parallel): no buffer
  /// of the whole range.
  std::uint32_t partition(const Task& task,
    const BinMap& map,
    int axis,
    int split,
    RangeBounds& left,
    RangeBounds& right,
    DefaultInitVector<BvhPrimBox>& scratch)
  {
    auto isLeft = [&](const glm::vec3& c) { return map.bin(c, axis) < split; };
    auto pass = [&](std::uint32_t b,
                  std::uint32_t e,
                  RangeBounds& l,
                  RangeBounds& r,
                  DefaultInitVector<BvhPrimBox>& rest) -> std::uint32_t
    {
      if (rest.size() < e - b)
      {
        rest.resize(e - b); // grown only: a shrink and regrow would zero it again
      }
      BvhPrimBox* out = this->prims.data() + b;
      std::size_t rights = 0;
      for (std::uint32_t i = b; i < e; ++i)
      {
        const BvhPrimBox& p = this->prims[i];
        const glm::vec3 c = centroidOf(p);
        if (isLeft(c))
        {
          l.grow(p, c);
          *out++ = p; // out <= &p: p is read before it may be overwritten
        }
        else
        {
          r.grow(p, c);
          rest[rights++] = p;
        }
      }
      std::copy(rest.begin(), rest.begin() + std::ptrdiff_t(rights), out);
      return static_cast<std::uint32_t>(out - this->prims.data()) - b;
    };
    if (!this->wide(task.end - task.begin))
    {
      return task.begin + pass(task.begin, task.end, left, right, scratch);
    }
    struct Side
    {
      std::uint32_t lefts = 0;
      RangeBounds left, right;
    };
    std::vector<Side> side(chunks(task.begin, task.end));
    forEachOnWorkers(side.size(),
      [&](std::size_t c, DefaultInitVector<BvhPrimBox>& rest)
      {
        side[c].lefts = pass(chunkBegin(task.begin, c),
          chunkEnd(task.begin, task.end, c),
          side[c].left,
          side[c].right,
          rest);
      });
    // Neighbouring runs (each its left side, then its right side) merged pairwise, the pairs of
    // a round in parallel: one rotation swaps the first run's right side with the second run's
    // left side. log2(chunks) rounds, each moving at most half the range.
    struct Run
    {
      std::uint32_t begin, lefts;
    };
    std::vector<Run> runs(side.size());
    for (std::size_t c = 0; c < side.size(); ++c)
    {
      left.grow(side[c].left);
      right.grow(side[c].right);
      runs[c] = { chunkBegin(task.begin, c), side[c].lefts };
    }
    while (runs.size() > 1)
    {
      std::vector<Run> merged((runs.size() + 1) / 2);
      parallelFor(merged.size(),
        this->threads,
        [&](std::size_t i)
        {
          const Run a = runs[2 * i];
          if (2 * i + 1 == runs.size())
          {
            merged[i] = a;
            return;
          }
          const Run b = runs[2 * i + 1];
          const auto first = this->prims.begin();
          std::rotate(first + a.begin + a.lefts, first + b.begin, first + b.begin + b.lefts);
          merged[i] = { a.begin, a.lefts + b.lefts };
        });
      runs.swap(merged);
    }
    return task.begin + runs[0].lefts;
  }

public:
  /// Calls body(i, scratch) for every i in [0, n) on up to `threads` workers, each with its own
  /// scratch, kept from call to call: a fresh buffer per chunk or subtree paid its first-touch
  /// page faults again every time. Items write only their own outputs, so the result does not
  /// depend on which worker ran them.
  template<typename Body>
  void forEachOnWorkers(std::size_t n, Body&& body)
  {
    const std::size_t workers = std::min(this->workerScratch.size(), n);
    std::atomic<std::size_t> next{ 0 };
    parallelFor(workers,
      this->threads,
      [&](std::size_t w)
      {
        for (std::size_t i = next++; i < n; i = next++)
        {
          body(i, this->workerScratch[w]);
        }
      });
  }
  /// The scratch of the calling thread's serial splits: worker 0's, which no forEachOnWorkers
  /// call uses at the same time (the top is split on the calling thread alone), so that at most
  /// one scratch per worker is ever held.
  DefaultInitVector<BvhPrimBox>& callerScratch() { return this->workerScratch[0]; }
  /// Frees the workers' scratch and returns its pages.
  void releaseScratch()
  {
    for (DefaultInitVector<BvhPrimBox>& s : this->workerScratch)
    {
      DefaultInitVector<BvhPrimBox>().swap(s);
    }
    releaseFreedMemory();
  }

private:
  DefaultInitVector<BvhPrimBox>& prims;
  const std::uint32_t maxLeafSize;
  const int threads;
  /// One per thread (never resized, so references stay valid); forEachOnWorkers.
  std::vector<DefaultInitVector<BvhPrimBox>> workerScratch;
};

/// A subtree built on its own: nodes[0] is the root of the range `task`.
struct Subtree
{
  Task task;
  DefaultInitVector<BvhNode> nodes;
  int depth = 0;
};
} // namespace

Bvh buildBvh(DefaultInitVector<BvhPrimBox> prims, int maxLeafSize, int threads)
{
  Bvh bvh;
  const std::uint32_t n = static_cast<std::uint32_t>(prims.size());
  if (n == 0)
  {
    return bvh;
  }
  Builder builder(prims, maxLeafSize, threads);
  const std::size_t leafSize = static_cast<std::size_t>(std::max(1, maxLeafSize));

  // 1. The top, on this thread; ranges of at most kSubtreePrims wait for step 2.
  bvh.nodes.push_back({});
  std::vector<Subtree> subtrees;
  std::vector<Task> stack{ { 0, 0, n, 1, builder.boundsOf(0, n) } };
  while (!stack.empty())
  {
    const Task task = stack.back();
    stack.pop_back();
    if (task.end - task.begin <= kSubtreePrims)
    {
      subtrees.push_back({ task, {}, 0 });
      continue;
    }
    builder.process(task, bvh.nodes, stack, bvh.depth, builder.callerScratch());
  }
  builder.releaseScratch(); // its pages returned: the subtrees' workers allocate their own
  // 2. The subtrees, in parallel, each rooted at its own node 0; their node arrays reserved on
  // this thread, 4 / leafSize per primitive (0.43 measured at leaf size 8; more grows).
  for (Subtree& sub : subtrees)
  {
    const std::size_t count = sub.task.end - sub.task.begin;
    sub.nodes.reserve(std::min(2 * count, 4 * count / leafSize + 1)); // never above 2n - 1
  }
  builder.forEachOnWorkers(subtrees.size(),
    [&](std::size_t i, DefaultInitVector<BvhPrimBox>& localScratch)
    {
      Subtree& sub = subtrees[i];
      sub.nodes.push_back({});
      Task root = sub.task;
      root.node = 0;
      std::vector<Task> local{ root };
      while (!local.empty())
      {
        const Task t = local.back();
        local.pop_back();
        builder.process(t, sub.nodes, local, sub.depth, localScratch);
      }
    });
  builder.releaseScratch();

  // The order is final: the references are kept, the boxes freed before the nodes are appended.
  bvh.prims.resize(n);
  std::transform(
    prims.begin(), prims.end(), bvh.prims.begin(), [](const BvhPrimBox& p) { return p.ref; });
  DefaultInitVector<BvhPrimBox>().swap(prims);

  // 3. Appended in order: the root takes its reserved slot, the rest follow at `base`; each
  // subtree's own array is freed once appended (the arrays are not held twice).
  std::size_t total = bvh.nodes.size();
  for (const Subtree& sub : subtrees)
  {
    total += sub.nodes.size() - 1;
  }
  bvh.nodes.reserve(total);
  for (Subtree& sub : subtrees)
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
    DefaultInitVector<BvhNode>().swap(sub.nodes);
  }
  return bvh;
}

} // namespace amrdm
