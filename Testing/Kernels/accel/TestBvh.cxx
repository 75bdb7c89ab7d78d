// The BVH builder: every primitive referenced once, every node bounding its subtree, point
// queries equal to brute force, and the tree identical node for node for every thread count
// (the top is split with chunked binning and partition, the subtrees are built in parallel).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "accel/BvhBuilder.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <random>

using namespace amrdm;

namespace
{

struct Boxes
{
  std::vector<glm::vec3> lo, hi;
  std::vector<std::uint32_t> refs;
};

/// n boxes of random size in the unit cube, clustered in a few places (uneven SAH splits)
/// with a fraction of exact duplicates (coincident centroids).
Boxes randomBoxes(std::uint32_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Boxes b;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    if (i > 0 && u(rng) < 0.05f)
    {
      b.lo.push_back(b.lo.back());
      b.hi.push_back(b.hi.back());
    }
    else
    {
      const float cluster = std::floor(u(rng) * 4.0f) * 0.25f;
      const glm::vec3 c(cluster + 0.25f * u(rng), u(rng), u(rng) * u(rng));
      const glm::vec3 h = 0.002f + 0.02f * glm::vec3(u(rng), u(rng), u(rng));
      b.lo.push_back(c - h);
      b.hi.push_back(c + h);
    }
    b.refs.push_back(makePrimRef(PrimGridlet, i));
  }
  return b;
}

/// The builder's input: one record per box.
DefaultInitVector<BvhPrimBox> records(const Boxes& b)
{
  DefaultInitVector<BvhPrimBox> r;
  for (std::size_t i = 0; i < b.refs.size(); ++i)
  {
    r.push_back({ b.lo[i], b.hi[i], b.refs[i] });
  }
  return r;
}

bool contains(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& p)
{
  return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

/// Walks the tree: each node's box holds its children's (or its primitives') boxes.
void checkNode(const Bvh& bvh, const Boxes& b, std::uint32_t node, int depth, int& maxDepth)
{
  const BvhNode& n = bvh.nodes[node];
  maxDepth = std::max(maxDepth, depth);
  if (n.count == 0)
  {
    REQUIRE(n.first + 1 < bvh.nodes.size());
    for (std::uint32_t c : { n.first, n.first + 1 })
    {
      CHECK(glm::all(glm::lessThanEqual(n.lo, bvh.nodes[c].lo)));
      CHECK(glm::all(glm::greaterThanEqual(n.hi, bvh.nodes[c].hi)));
      checkNode(bvh, b, c, depth + 1, maxDepth);
    }
    return;
  }
  for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
  {
    const std::uint32_t p = primIndex(bvh.prims[i]);
    CHECK(glm::all(glm::lessThanEqual(n.lo, b.lo[p])));
    CHECK(glm::all(glm::greaterThanEqual(n.hi, b.hi[p])));
  }
}

} // namespace

TEST_CASE("every primitive once, every node bounds its subtree, depth within the stack")
{
  for (std::uint32_t n : { 1u, 5u, 1000u, 150000u })
  {
    const Boxes b = randomBoxes(n, 7u + n);
    const Bvh bvh = buildBvh(records(b), 4, 0);
    std::vector<std::uint32_t> prims(bvh.prims.begin(), bvh.prims.end());
    std::sort(prims.begin(), prims.end());
    CHECK(prims == b.refs);
    int maxDepth = 0;
    checkNode(bvh, b, 0, 1, maxDepth);
    CHECK(maxDepth == bvh.depth);
    CHECK(bvh.depth <= kBvhMaxDepth);
  }
}

TEST_CASE("the same tree, node for node, on 1, 2, 3 and all threads")
{
  // 150000 primitives: the top nodes take the chunked (parallel) binning and partition, and
  // dozens of subtrees are built in parallel.
  const Boxes b = randomBoxes(150000, 3);
  const Bvh one = buildBvh(records(b), 4, 1);
  for (int threads : { 2, 3, 0 })
  {
    const Bvh other = buildBvh(records(b), 4, threads);
    REQUIRE(other.nodes.size() == one.nodes.size());
    CHECK(
      std::memcmp(other.nodes.data(), one.nodes.data(), one.nodes.size() * sizeof(BvhNode)) == 0);
    CHECK(other.prims == one.prims);
    CHECK(other.depth == one.depth);
  }
}

TEST_CASE("point queries reach exactly the boxes that contain the point")
{
  const Boxes b = randomBoxes(60000, 11);
  const Bvh bvh = buildBvh(records(b), 4, 0);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int hits = 0;
  for (int q = 0; q < 400; ++q)
  {
    // Half the points at a box corner (on the boundary, which counts as inside).
    const std::uint32_t k = static_cast<std::uint32_t>(q * 131) % 60000u;
    const glm::vec3 p = q % 2 ? b.lo[k] : glm::vec3(u(rng), u(rng), u(rng));
    std::vector<std::uint32_t> found, expected;
    bvhPointQuery(bvh.view(),
      p,
      [&](std::uint32_t ref)
      {
        // The query visits every primitive of a leaf whose box holds p; the caller tests its
        // own box (the element test), as here.
        const std::uint32_t i = primIndex(ref);
        if (contains(b.lo[i], b.hi[i], p))
        {
          found.push_back(ref);
        }
        return false;
      });
    for (std::uint32_t i = 0; i < b.refs.size(); ++i)
    {
      if (contains(b.lo[i], b.hi[i], p))
      {
        expected.push_back(b.refs[i]);
      }
    }
    std::sort(found.begin(), found.end());
    CHECK(found == expected);
    hits += static_cast<int>(found.size());
  }
  CHECK(hits > 200); // the queries did hit boxes
}
