// Dual-mesh construction and field properties on synthetic hierarchies (kernel only, no VTK):
// construction equals a brute-force one, linear fields are reproduced, the mesh is watertight
// and single-valued, output is thread-count independent, one level needs no stitching, and bad
// input is refused with a message.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "BruteForceDual.h"
#include "mesh/DualMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <chrono>
#include <cstring>
#include <random>

using namespace amrdm;
using amrdm_test::makeSynthetic;
using amrdm_test::SyntheticOptions;

namespace
{
/// Tolerance of the field checks, relative to the field's range (the 1e-5).
constexpr double kRelativeTolerance = 1e-5;

struct Linear
{
  glm::dvec3 a;
  double b;
  float operator()(const glm::dvec3& p) const { return static_cast<float>(glm::dot(a, p) + b); }
};

DualMesh build(AmrHierarchy& amr, int threads = 0, int gridletSize = 8)
{
  amr.validate();
  amr.finalizeCellStates();
  DualMeshBuildOptions options;
  options.threads = threads;
  options.gridletSize = gridletSize;
  return buildDualMesh(amr, options);
}

/// Random points at least one coarsest cell inside the level-0 domain. Half of them are snapped
/// to lattice planes of a random level (faces, edges, vertices of dual cells).
std::vector<glm::vec3> randomPoints(std::mt19937& rng,
  const AmrHierarchy& amr,
  const glm::ivec3& rootCells,
  std::size_t n)
{
  const double w0 = static_cast<double>(amr.levelWidth(0));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::vec3> points(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    glm::dvec3 p;
    for (int d = 0; d < 3; ++d)
    {
      p[d] = w0 + u(rng) * (rootCells[d] * w0 - 2.0 * w0);
    }
    if (i % 2 == 1)
    {
      const int level = static_cast<int>(rng() % static_cast<unsigned>(amr.numLevels()));
      const double w = static_cast<double>(amr.levelWidth(level));
      const int axes = 1 + static_cast<int>(rng() % 3u);
      for (int d = 0; d < axes; ++d)
      {
        p[d] = (std::floor(p[d] / w - 0.5) + 0.5) * w; // a cell-centre plane of that level
        p[d] = std::max(w0, std::min(p[d], rootCells[d] * w0 - w0));
      }
    }
    points[i] = glm::vec3(p);
  }
  return points;
}

SyntheticOptions optionsFor(unsigned seed, int levels)
{
  SyntheticOptions opt;
  opt.levels = levels;
  opt.rootCells = glm::ivec3(6 + static_cast<int>(seed % 4), 5 + static_cast<int>(seed % 3), 6);
  opt.boxesPerLevel = 2 + static_cast<int>(seed % 3);
  return opt;
}
} // namespace

TEST_CASE("construction equals an independent brute-force construction")
{
  long long total = 0;
  for (unsigned seed = 1; seed <= 40; ++seed)
  {
    SyntheticOptions opt = optionsFor(seed, 2 + static_cast<int>(seed % 3));
    opt.rootCells = glm::ivec3(4 + static_cast<int>(seed % 3));
    opt.maxBoxCells = 3;
    AmrHierarchy amr = makeSynthetic(seed, opt, [](const glm::dvec3&) { return 1.0f; });
    DualMesh mesh = build(amr);
    const amrdm_test::BruteForceResult truth = amrdm_test::bruteForceDual(amr);
    long long perfect = 0;
    for (long long n : truth.perfectPerLevel)
      perfect += n;
    CHECK(mesh.counts.perfectCubes == perfect);
    std::vector<amrdm_test::CornerSet> ours;
    for (int t = 0; t < kElementKindCount; ++t)
    {
      const int n = elementCorners(t);
      for (std::int64_t e = 0; e < mesh.numElements(t); ++e)
      {
        amrdm_test::CornerSet set;
        for (int v = 0; v < n; ++v)
        {
          const glm::ivec3 p2 = mesh.vertices[mesh.elementIndices[t][e * n + v]].pos2;
          set.push_back({ p2.x, p2.y, p2.z });
        }
        std::sort(set.begin(), set.end());
        set.erase(std::unique(set.begin(), set.end()), set.end());
        // Distinct corners: all of them, except for hexes, which may repeat corners.
        if (t != int(ElementKind::Hex))
          CHECK(set.size() == std::size_t(n));
        else
          CHECK(set.size() >= 5);
        ours.push_back(set);
      }
    }
    std::sort(ours.begin(), ours.end());
    CHECK_MESSAGE(ours == truth.stitching, "seed ", seed);
    total += static_cast<long long>(ours.size());
  }
  MESSAGE("stitching elements compared: ", total);
  CHECK(total > 0);
}

TEST_CASE("linear reproduction, watertightness and single values on 2-6 level hierarchies")
{
  std::mt19937 rng(7);
  std::size_t totalPoints = 0, misses = 0, multi = 0;
  double worstLinear = 0.0, worstSpread = 0.0;
  DualMeshCounts sum;
  for (int levels = 2; levels <= 6; ++levels)
  {
    for (unsigned seed = 100; seed < 104; ++seed)
    {
      const SyntheticOptions opt = optionsFor(seed + static_cast<unsigned>(levels), levels);
      const Linear f{ glm::dvec3(0.7, -1.3, 0.45), 3.0 };
      AmrHierarchy amr = makeSynthetic(seed * 31u + static_cast<unsigned>(levels), opt, f);
      DualMesh mesh = build(amr);
      for (int k = 0; k < kElementKindCount; ++k)
        sum.elements(k) += mesh.counts.elements(k);
      sum.degenerateHexes += mesh.counts.degenerateHexes;
      sum.gridlets += mesh.counts.gridlets;
      const DualMeshView view = mesh.view();
      const double w0 = static_cast<double>(amr.levelWidth(0));
      const glm::dvec3 extent = glm::dvec3(opt.rootCells) * w0;
      const double range =
        std::abs(f.a.x) * extent.x + std::abs(f.a.y) * extent.y + std::abs(f.a.z) * extent.z;
      const std::vector<glm::vec3> points = randomPoints(rng, amr, opt.rootCells, 5000);
      for (const glm::vec3& p : points)
      {
        float value;
        if (!sampleField(view, p, ElementTestParams{}, value))
        {
          ++misses;
          continue;
        }
        worstLinear = std::max(worstLinear, std::abs(value - f(glm::dvec3(p))) / range);
      }
      totalPoints += points.size();

      // Single-valued: a random (non-linear) field, every claiming primitive must agree.
      std::mt19937 valueRng(seed);
      for (AmrBlock& block : amr.blocks)
        for (float& v : block.values)
          v = std::uniform_real_distribution<float>(0.0f, 1.0f)(valueRng);
      DualMesh noisy = build(amr);
      const DualMeshView nview = noisy.view();
      for (const glm::vec3& p : points)
      {
        float values[16];
        std::uint32_t refs[16];
        const int hits = sampleFieldAllHits(nview, p, ElementTestParams{}, values, refs, 16);
        if (hits == 0)
        {
          ++misses;
        }
        multi += hits > 1 ? 1 : 0;
        for (int h = 1; h < hits; ++h)
          worstSpread = std::max(worstSpread, double(std::abs(values[h] - values[0])));
      }
      totalPoints += points.size();
    }
  }
  MESSAGE(
    "points: ", totalPoints, ", misses: ", misses, ", points claimed more than once: ", multi);
  MESSAGE("worst linear error / range: ",
    worstLinear,
    ", worst spread between claims / range: ",
    worstSpread);
  MESSAGE("elements: tets ",
    sum.tets,
    ", pyramids ",
    sum.pyramids,
    ", wedges ",
    sum.wedges,
    ", hexes ",
    sum.hexes,
    " (degenerate ",
    sum.degenerateHexes,
    "), gridlets ",
    sum.gridlets);
  CHECK(misses == 0);
  CHECK(worstLinear <= kRelativeTolerance);
  CHECK(worstSpread <= kRelativeTolerance);
  // Tets need a face collapsed to a point plus a collapsed base edge; 2:1 ratio-2 hierarchies
  // produce none (the element tests cover tets directly).
  CHECK(sum.pyramids > 0);
  CHECK(sum.wedges > 0);
  CHECK(sum.hexes > 0);
}

TEST_CASE("output is identical for 1 and 2 threads")
{
  SyntheticOptions opt = optionsFor(3, 4);
  AmrHierarchy a = makeSynthetic(99, opt, [](const glm::dvec3& p) { return float(p.x * p.y); });
  AmrHierarchy b = a;
  DualMesh m1 = build(a, 1), m2 = build(b, 2);
  CHECK(m1.gridlets.size() == m2.gridlets.size());
  CHECK(std::memcmp(
          m1.gridlets.data(), m2.gridlets.data(), m1.gridlets.size() * sizeof(GridletHeader)) == 0);
  CHECK(std::memcmp(m1.gridletScalars.data(),
          m2.gridletScalars.data(),
          m1.gridletScalars.size() * sizeof(float)) == 0);
  CHECK(m1.vertices.size() == m2.vertices.size());
  CHECK(std::memcmp(
          m1.vertices.data(), m2.vertices.data(), m1.vertices.size() * sizeof(ElementVertex)) == 0);
  for (int t = 0; t < kElementKindCount; ++t)
    CHECK(m1.elementIndices[t] == m2.elementIndices[t]);
  CHECK(m1.bvh.prims == m2.bvh.prims);
}

TEST_CASE("one level needs no stitching element: its boundary cubes join the gridlets, under 6.5 "
          "bytes per leaf cell")
{
  AmrHierarchy amr;
  amr.ratio = { 1 };
  const glm::ivec3 split(48, 64, 64);
  for (int b = 0; b < 2; ++b) // two touching blocks: 96 x 64 x 64 cells
  {
    AmrBlock block;
    block.level = 0;
    block.lower = glm::ivec3(b * split.x, 0, 0);
    block.dims = split;
    block.values.assign(static_cast<std::size_t>(block.numCells()), 1.0f);
    amr.blocks.push_back(block);
  }
  const auto start = std::chrono::steady_clock::now();
  DualMesh mesh = build(amr);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const MemoryReport mem = mesh.memoryReport();
  MESSAGE("one level, ",
    mesh.counts.leafCells,
    " cells: ",
    mem.bytesPerLeafCell(),
    " B/leaf cell, ",
    mesh.counts.gridlets,
    " gridlets, BVH ",
    mesh.bvh.nodes.size(),
    " nodes, built in ",
    seconds,
    " s");
  // Every dual cell of the lattice extended by one ghost position per face is a perfect cube of
  // the level or a boundary cube (a ghost corner): all in gridlets, no element, no vertex.
  CHECK(mesh.counts.perfectCubes == 97LL * 65 * 65);
  CHECK(mesh.counts.totalElements() == 0);
  CHECK(mesh.vertices.empty());
  // Gridlets of 8 dual cells a side from one cell below the lower faces: 97 = 12 * 8 + 1.
  CHECK(mesh.counts.gridlets == 13LL * 9 * 9);
  const double gridletBytes = double(mem.gridletScalars + mem.gridletHeaders);
  MESSAGE("gridlets ", gridletBytes / double(mem.leafCells), " B/leaf cell");
  CHECK(gridletBytes / double(mem.leafCells) <= 6.5);
  CHECK(mem.bytesPerLeafCell() <= 7.0);
  // The box reaches the domain faces and no further.
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  CHECK(lo == glm::vec3(0.0f));
  CHECK(hi == glm::vec3(96.0f, 64.0f, 64.0f));
}

TEST_CASE("bad input is refused with a message")
{
  auto expectError = [](AmrHierarchy amr, const char* fragment)
  {
    try
    {
      amr.finalizeCellStates();
      buildDualMesh(amr);
      FAIL("no error for: ", fragment);
    }
    catch (const std::invalid_argument& e)
    {
      MESSAGE(std::string(e.what()));
      CHECK(std::string(e.what()).find(fragment) != std::string::npos);
    }
  };
  AmrBlock block;
  block.level = 0;
  block.dims = glm::ivec3(2);
  block.values.assign(8, 0.0f);
  AmrHierarchy ok;
  ok.ratio = { 1 };
  ok.blocks = { block };

  expectError(AmrHierarchy(), "no levels");
  AmrHierarchy badRatio = ok;
  badRatio.ratio = { 1, 1 };
  expectError(badRatio, "ratio");
  AmrHierarchy empty = ok;
  empty.blocks[0].dims = glm::ivec3(0, 2, 2);
  empty.blocks[0].values.clear();
  expectError(empty, "empty dimensions");
  AmrHierarchy wrongSize = ok;
  wrongSize.blocks[0].values.resize(3);
  expectError(wrongSize, "values");
  AmrHierarchy overlap = ok;
  overlap.blocks.push_back(block);
  overlap.blocks[1].lower = glm::ivec3(1, 1, 1);
  expectError(overlap, "overlap");
  AmrHierarchy badLevel = ok;
  badLevel.blocks[0].level = 3;
  expectError(badLevel, "level");
  DualMeshBuildOptions opts;
  opts.gridletSize = 1;
  AmrHierarchy good = ok;
  good.finalizeCellStates();
  CHECK_THROWS_WITH_AS(
    buildDualMesh(good, opts), doctest::Contains("gridlet size"), std::invalid_argument);
}

namespace
{
/// Root 8^3 at level 0, then per finer level a box in the lower corner of the previous one, so
/// the finest level touches level 0 (a jump of levels-1 levels).
AmrHierarchy nestedCorner(int ratio, int levels, unsigned seed)
{
  AmrHierarchy amr;
  amr.ratio.assign(static_cast<std::size_t>(levels), ratio);
  amr.ratio[0] = 1;
  glm::ivec3 lo(2);
  for (int l = 0; l < levels; ++l)
  {
    AmrBlock b;
    b.level = l;
    b.lower = l == 0 ? glm::ivec3(0) : lo;
    b.dims = l == 0 ? glm::ivec3(8) : glm::ivec3(l == 1 ? 4 : 2) * ratio;
    lo *= ratio;
    amr.blocks.push_back(b);
  }
  std::mt19937 rng(seed);
  for (AmrBlock& b : amr.blocks)
  {
    b.values.resize(static_cast<std::size_t>(b.numCells()));
    for (float& v : b.values)
      v = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
  }
  amr.finalizeCellStates();
  return amr;
}

/// Misses and worst spread between claims at random points inside the level-0 domain.
void probe(const AmrHierarchy& amr, const DualMesh& mesh, long& misses, double& spread)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double w0 = static_cast<double>(amr.levelWidth(0));
  misses = 0;
  spread = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    const glm::vec3 p(glm::dvec3(w0) + glm::dvec3(u(rng), u(rng), u(rng)) * (6.0 * w0));
    float values[16];
    std::uint32_t refs[16];
    const int hits = sampleFieldAllHits(mesh.view(), p, ElementTestParams{}, values, refs, 16);
    misses += hits == 0;
    for (int h = 1; h < hits; ++h)
      spread = std::max(spread, double(std::abs(values[h] - values[0])));
  }
}
} // namespace

TEST_CASE("ratios 3 and 4, and level jumps up to a width factor of 4, stay watertight")
{
  for (int ratio : { 3, 4 })
  {
    long totalMisses = 0;
    double worst = 0.0;
    for (unsigned seed = 1; seed <= 12; ++seed)
    {
      SyntheticOptions opt = optionsFor(seed, 3);
      opt.ratio = ratio;
      opt.maxBoxCells = 3;
      const Linear f{ glm::dvec3(0.3, -0.7, 1.1), 0.5 };
      AmrHierarchy amr = makeSynthetic(seed, opt, f);
      DualMesh mesh = build(amr);
      const double w0 = static_cast<double>(amr.levelWidth(0));
      const double range = 2.1 * 10.0 * w0;
      std::mt19937 rng(seed);
      for (const glm::vec3& p : randomPoints(rng, amr, opt.rootCells, 3000))
      {
        float v;
        if (!sampleField(mesh.view(), p, ElementTestParams{}, v))
        {
          ++totalMisses;
          continue;
        }
        worst = std::max(worst, std::abs(v - f(glm::dvec3(p))) / range);
      }
    }
    MESSAGE("ratio ", ratio, ": misses ", totalMisses, ", worst linear error / range ", worst);
    CHECK(totalMisses == 0);
    CHECK(worst <= kRelativeTolerance);
  }
  // Jumps: (ratio, levels) whose finest level touches level 0.
  struct Case
  {
    int ratio, levels;
    bool supported;
  };
  for (const Case c : { Case{ 2, 3, true },
         Case{ 4, 2, true },
         Case{ 2, 4, false },
         Case{ 8, 2, false },
         Case{ 4, 3, false } })
  {
    AmrHierarchy amr = nestedCorner(c.ratio, c.levels, 9);
    if (c.supported)
    {
      DualMesh mesh = buildDualMesh(amr);
      long misses;
      double spread;
      probe(amr, mesh, misses, spread);
      MESSAGE("ratio ",
        c.ratio,
        ", ",
        c.levels - 1,
        "-level jump: misses ",
        misses,
        ", worst spread between claims ",
        spread);
      CHECK(misses == 0);
      CHECK(spread <= kRelativeTolerance);
    }
    else
    {
      CHECK_THROWS_WITH_AS(
        buildDualMesh(amr), doctest::Contains("at most a factor of 4"), std::invalid_argument);
    }
  }
}
