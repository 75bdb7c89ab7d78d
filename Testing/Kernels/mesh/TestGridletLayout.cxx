// The gridlet layout from work items' pieces (mesh/GridletLayout.h) against brute force: random
// perfect-cube runs on several levels, negative lattice positions included, split into work
// items in random ways and orders, give one range per level and aligned block of G cubes, the
// bounding range of that block's cubes, in order of level, z, y, x; a run outside its item's
// range is refused with a message.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/GridletLayout.h"

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>

using namespace amrdm;

namespace
{

struct Run
{
  int level;
  glm::ivec3 lower;
  int length;
};

using Key = std::tuple<int, int, int, int>; // level, z, y, x: the layout's order

/// Per aligned block, the bounding range of its cubes' lower corners, cube by cube.
std::vector<GridletRange> bruteForce(const std::vector<Run>& runs,
  const std::vector<glm::ivec3>& origin,
  int G)
{
  std::map<Key, GridletRange> blocks;
  for (const Run& r : runs)
  {
    for (int i = 0; i < r.length; ++i)
    {
      const glm::ivec3 c = r.lower + glm::ivec3(i, 0, 0);
      const glm::ivec3 o = origin[static_cast<std::size_t>(r.level)];
      const Key k{
        r.level, floorDiv(c.z - o.z, G), floorDiv(c.y - o.y, G), floorDiv(c.x - o.x, G)
      };
      auto it = blocks.find(k);
      if (it == blocks.end())
      {
        blocks[k] = { r.level, c, c };
      }
      else
      {
        it->second.lo = glm::min(it->second.lo, c);
        it->second.hi = glm::max(it->second.hi, c);
      }
    }
  }
  std::vector<GridletRange> out;
  for (const auto& kv : blocks)
  {
    out.push_back(kv.second);
  }
  return out;
}

void requireSame(const std::vector<GridletRange>& a, const std::vector<GridletRange>& b)
{
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    CHECK(a[i].level == b[i].level);
    CHECK(a[i].lo == b[i].lo);
    CHECK(a[i].hi == b[i].hi);
  }
}

} // namespace

TEST_CASE("pieces united over random item splits equal the brute-force layout")
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial)
  {
    const int G = 1 + int(rng() % 9);
    const int levels = 1 + int(rng() % 3);
    std::vector<glm::ivec3> origin;
    for (int l = 0; l < levels; ++l)
    {
      origin.push_back(glm::ivec3(int(rng() % 7) - 4, int(rng() % 7) - 4, int(rng() % 7) - 4));
    }
    // Items: a level and a box of lower corners; runs inside it.
    struct Item
    {
      int level;
      glm::ivec3 lo, hi;
      std::vector<Run> runs;
    };
    std::vector<Item> items(1 + rng() % 12);
    std::vector<Run> all;
    for (Item& item : items)
    {
      item.level = int(rng() % unsigned(levels));
      item.lo = glm::ivec3(int(rng() % 41) - 20, int(rng() % 41) - 20, int(rng() % 41) - 20);
      item.hi = item.lo + glm::ivec3(int(rng() % 30), int(rng() % 8), int(rng() % 8));
      const int n = int(rng() % 20);
      for (int r = 0; r < n; ++r)
      {
        const glm::ivec3 size = item.hi - item.lo + 1;
        glm::ivec3 at = item.lo + glm::ivec3(int(rng() % unsigned(size.x)),
                                    int(rng() % unsigned(size.y)),
                                    int(rng() % unsigned(size.z)));
        const int length = 1 + int(rng() % unsigned(item.hi.x - at.x + 1));
        item.runs.push_back({ item.level, at, length });
        all.push_back(item.runs.back());
      }
    }
    const std::vector<GridletRange> expected = bruteForce(all, origin, G);
    for (int order = 0; order < 3; ++order)
    {
      std::shuffle(items.begin(), items.end(), rng);
      ItemGridletPieces collector; // reused from item to item, as a worker does
      std::vector<GridletPiece> pieces;
      std::int64_t cubes = 0, expectedCubes = 0;
      for (const Item& item : items)
      {
        collector.begin(
          item.level, origin[static_cast<std::size_t>(item.level)], G, item.lo, item.hi);
        for (const Run& r : item.runs)
        {
          collector.addRun(r.lower, r.length);
          expectedCubes += r.length;
        }
        const std::size_t before = pieces.size();
        cubes += collector.finish(pieces);
        CHECK(pieces.size() - before <=
              std::size_t(alignedBlocksTouched(
                origin[static_cast<std::size_t>(item.level)], G, item.lo, item.hi)));
      }
      CHECK(cubes == expectedCubes);
      requireSame(gridletLayout(pieces), expected);
    }
  }
}

TEST_CASE("a run outside its item's range is refused with a message")
{
  ItemGridletPieces collector;
  collector.begin(0, glm::ivec3(-1), 8, glm::ivec3(0), glm::ivec3(15, 3, 3));
  CHECK_NOTHROW(collector.addRun(glm::ivec3(0, 0, 0), 16));
  CHECK_THROWS_WITH_AS(collector.addRun(glm::ivec3(0, 9, 0), 1),
    doctest::Contains("outside its work item's range"),
    std::out_of_range);
  CHECK_THROWS_AS(collector.addRun(glm::ivec3(10, 0, 0), 20), std::out_of_range);
  CHECK_THROWS_AS(collector.addRun(glm::ivec3(0, 0, 0), 0), std::out_of_range);
}

TEST_CASE("no cubes, no gridlets")
{
  ItemGridletPieces collector;
  collector.begin(0, glm::ivec3(-1), 8, glm::ivec3(0), glm::ivec3(7));
  std::vector<GridletPiece> pieces;
  CHECK(collector.finish(pieces) == 0);
  CHECK(pieces.empty());
  CHECK(gridletLayout(pieces).empty());
}
