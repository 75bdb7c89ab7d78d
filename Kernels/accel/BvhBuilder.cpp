// Binned-SAH BVH construction (host). Children of a node are stored next to each other, so an
// inner node needs one index. The build order is fixed, so the tree is deterministic.
#include "accel/Bvh.h"

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
} // namespace

Bvh buildBvh(const std::vector<glm::vec3>& lo,
  const std::vector<glm::vec3>& hi,
  const std::vector<std::uint32_t>& refs,
  int maxLeafSize)
{
  if (lo.size() != hi.size() || lo.size() != refs.size())
  {
    throw std::invalid_argument("buildBvh: box and reference arrays differ in length");
  }
  Bvh bvh;
  const std::uint32_t n = static_cast<std::uint32_t>(refs.size());
  if (n == 0)
  {
    return bvh;
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::vector<glm::vec3> centroid(n);
  for (std::uint32_t i = 0; i < n; ++i)
  {
    centroid[i] = 0.5f * (lo[i] + hi[i]);
  }
  bvh.nodes.reserve(2 * static_cast<std::size_t>(n) / std::max(1, maxLeafSize) + 1);
  bvh.nodes.push_back({});
  std::vector<Task> stack{ { 0, 0, n, 1 } };
  while (!stack.empty())
  {
    const Task task = stack.back();
    stack.pop_back();
    Box bounds, cbounds;
    for (std::uint32_t i = task.begin; i < task.end; ++i)
    {
      bounds.grow(lo[order[i]], hi[order[i]]);
      cbounds.grow(centroid[order[i]], centroid[order[i]]);
    }
    const std::uint32_t count = task.end - task.begin;
    auto makeLeaf = [&]() { bvh.nodes[task.node] = { bounds.lo, task.begin, bounds.hi, count }; };
    // Turns the node into an inner node with children [begin, mid) and [mid, end).
    auto split = [&](std::uint32_t mid)
    {
      const std::uint32_t child = static_cast<std::uint32_t>(bvh.nodes.size());
      bvh.nodes.push_back({});
      bvh.nodes.push_back({});
      bvh.nodes[task.node] = { bounds.lo, child, bounds.hi, 0 };
      stack.push_back({ child + 1, mid, task.end, task.depth + 1 });
      stack.push_back({ child, task.begin, mid, task.depth + 1 });
    };
    bvh.depth = std::max(bvh.depth, task.depth);
    if (count <= static_cast<std::uint32_t>(maxLeafSize) || task.depth >= kBvhMaxDepth - 1)
    {
      makeLeaf();
      continue;
    }
    // Best binned SAH split over the three axes.
    float bestCost = std::numeric_limits<float>::max();
    int bestAxis = -1, bestSplit = 0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const float extent = cbounds.hi[axis] - cbounds.lo[axis];
      if (!(extent > 0.0f))
      {
        continue;
      }
      const float scale = kSahBins / extent;
      Box binBox[kSahBins];
      std::uint32_t binCount[kSahBins] = {};
      for (std::uint32_t i = task.begin; i < task.end; ++i)
      {
        const std::uint32_t p = order[i];
        const int b =
          std::min(kSahBins - 1, static_cast<int>((centroid[p][axis] - cbounds.lo[axis]) * scale));
        binBox[b].grow(lo[p], hi[p]);
        ++binCount[b];
      }
      float rightArea[kSahBins];
      std::uint32_t rightCount[kSahBins];
      Box acc;
      std::uint32_t accCount = 0;
      for (int b = kSahBins - 1; b > 0; --b)
      {
        acc.grow(binBox[b]);
        accCount += binCount[b];
        rightArea[b] = acc.area();
        rightCount[b] = accCount;
      }
      acc = Box();
      accCount = 0;
      for (int b = 0; b < kSahBins - 1; ++b)
      {
        acc.grow(binBox[b]);
        accCount += binCount[b];
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
    if (bestAxis < 0 || (count <= 2u * static_cast<std::uint32_t>(maxLeafSize) &&
                          kTraversalCost * bounds.area() + bestCost >= leafCost))
    {
      if (bestAxis < 0 && count > static_cast<std::uint32_t>(maxLeafSize))
      {
        // All centroids coincide: split the list in half to bound leaf size.
        split(task.begin + count / 2);
        continue;
      }
      makeLeaf();
      continue;
    }
    const float extent = cbounds.hi[bestAxis] - cbounds.lo[bestAxis];
    const float scale = kSahBins / extent;
    auto left = [&](std::uint32_t p)
    {
      return std::min(kSahBins - 1,
               static_cast<int>((centroid[p][bestAxis] - cbounds.lo[bestAxis]) * scale)) <
             bestSplit;
    };
    split(static_cast<std::uint32_t>(
      std::stable_partition(order.begin() + task.begin, order.begin() + task.end, left) -
      order.begin()));
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
