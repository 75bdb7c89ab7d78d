// BoxIndex against brute force: on random boxes (disjoint AMR-like tilings, overlapping clutter,
// one huge box among small ones, a sparse spread over a wide domain, inverted boxes) every query
// reports exactly the boxes that share a cell with it, each once.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/BoxIndex.h"

#include <algorithm>
#include <random>

using namespace amrdm;

namespace
{

CellBox randomBox(std::mt19937& rng, std::int64_t span, std::int64_t maxExtent)
{
  std::uniform_int_distribution<std::int64_t> at(-span, span);
  std::uniform_int_distribution<std::int64_t> ext(1, maxExtent);
  CellBox b;
  for (int d = 0; d < 3; ++d)
  {
    b.lower[d] = at(rng);
    b.upper[d] = b.lower[d] + ext(rng) - 1;
  }
  return b;
}

void checkAgainstBruteForce(const std::vector<CellBox>& boxes, std::mt19937& rng, std::int64_t span)
{
  const BoxIndex index(boxes);
  REQUIRE(index.size() == boxes.size());
  for (int q = 0; q < 300; ++q)
  {
    const CellBox query = randomBox(rng, span, std::max<std::int64_t>(1, span / 3));
    std::vector<std::size_t> found;
    index.forEachOverlap(query, [&](std::size_t i) { found.push_back(i); });
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < boxes.size(); ++i)
    {
      const CellBox& b = boxes[i];
      const bool valid = b.upper.x >= b.lower.x && b.upper.y >= b.lower.y && b.upper.z >= b.lower.z;
      if (valid && BoxIndex::overlaps(b, query))
      {
        expected.push_back(i);
      }
    }
    std::sort(found.begin(), found.end());
    CHECK(std::adjacent_find(found.begin(), found.end()) == found.end()); // each once
    CHECK(found == expected);
  }
}

} // namespace

TEST_CASE("a tiling of disjoint blocks: each query finds exactly the blocks it touches")
{
  std::mt19937 rng(7);
  std::vector<CellBox> boxes;
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 7; ++x)
      {
        CellBox b;
        b.lower = glm::i64vec3(x * 16, y * 12, z * 8);
        b.upper = b.lower + glm::i64vec3(15, 11, 7);
        boxes.push_back(b);
      }
  checkAgainstBruteForce(boxes, rng, 120);
}

TEST_CASE("overlapping, huge, sparse and inverted boxes")
{
  std::mt19937 rng(11);
  for (const std::int64_t span : { 10, 1000, 1000000000 })
  {
    std::vector<CellBox> boxes;
    for (int i = 0; i < 200; ++i)
    {
      boxes.push_back(randomBox(rng, span, std::max<std::int64_t>(1, span / 20)));
    }
    boxes.push_back(randomBox(rng, span, 2 * span)); // one box over most of the domain
    CellBox inverted;
    inverted.lower = glm::i64vec3(0, 0, 0);
    inverted.upper = glm::i64vec3(5, -1, 5);
    boxes.push_back(inverted);
    checkAgainstBruteForce(boxes, rng, span);
  }
}

TEST_CASE("no boxes, or only inverted ones: nothing is reported")
{
  std::mt19937 rng(3);
  checkAgainstBruteForce({}, rng, 10);
  checkAgainstBruteForce({ CellBox{} }, rng, 10);
}
