// Vertex-centred (point-data) AMR on synthetic hierarchies (kernel only, no VTK): linear fields
// reproduced at random points with no miss, no jump across level transitions (pairs of points
// 1e-7 apart on both sides of a refined block's faces, also where the levels' values disagree),
// a refined cell whose corners all lie on leaves is not claimed by the coarse gridlet, the
// output does not depend on the thread count, and bad input is refused with a message.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/DualMeshBuilder.h"
#include "mesh/VertexMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <cmath>
#include <cstring>
#include <functional>
#include <random>

using namespace amrdm;
using amrdm_test::makeSynthetic;
using amrdm_test::SyntheticOptions;
using amrdm_test::withPointData;

namespace
{
constexpr double kRelativeTolerance = 1e-5; // the 1e-5 of the range

DualMesh build(AmrHierarchy& amr, int threads = 0)
{
  amr.validate();
  amr.finalizeCellStates();
  DualMeshBuildOptions options;
  options.threads = threads;
  return buildDualMesh(amr, options);
}

bool sample(const DualMesh& mesh, const glm::dvec3& p, float& v, SampleHit* hit = nullptr)
{
  return sampleField(mesh.view(), p, ElementTestParams(), v, hit);
}

SyntheticOptions options(int levels, int ratio)
{
  SyntheticOptions o;
  o.levels = levels;
  o.ratio = ratio;
  o.rootCells = glm::ivec3(8, 7, 9);
  o.boxesPerLevel = 3;
  o.maxBoxCells = 4;
  return o;
}

double smooth(const glm::dvec3& p)
{
  return std::sin(0.11 * p.x) * std::cos(0.07 * p.y) + 0.02 * p.z * p.z / 64.0;
}
} // namespace

TEST_CASE("linear fields are reproduced at random points with no miss")
{
  std::mt19937 rng(7);
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    const int ratio = seed % 3 == 0 ? 4 : 2;
    AmrHierarchy cells =
      makeSynthetic(seed, options(seed % 2 ? 3 : 4, ratio), [](auto&) { return 0.f; });
    const glm::dvec3 a(0.3, -1.7, 0.9);
    AmrHierarchy amr =
      withPointData(cells, [&](const glm::dvec3& p, int) { return glm::dot(a, p) + 5.0; });
    const DualMesh mesh = build(amr);
    CHECK(mesh.gridletOrigin == 0.0f);
    CHECK(mesh.counts.totalElements() == 0);
    CHECK(mesh.counts.leafCells == amr.numLeafCells());
    const GridBox box = amr.domainBox();
    const glm::dvec3 lo(box.lower), hi(box.upper);
    double range = 0.0;
    for (int k = 0; k < 8; ++k)
    {
      const glm::dvec3 c(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
      range = std::max(range, std::abs(glm::dot(a, c - lo)));
    }
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int misses = 0;
    double worst = 0.0;
    for (int i = 0; i < 10000; ++i)
    {
      const glm::dvec3 p = lo + glm::dvec3(u(rng), u(rng), u(rng)) * (hi - lo);
      float v;
      if (!sample(mesh, p, v))
      {
        ++misses;
        continue;
      }
      worst = std::max(worst, std::abs(double(v) - (glm::dot(a, p) + 5.0)) / range);
    }
    INFO("seed " << seed << " ratio " << ratio << " levels " << amr.numLevels());
    CHECK(misses == 0);
    CHECK(worst <= kRelativeTolerance);
  }
}

TEST_CASE("no jump across level transitions, also where the levels disagree")
{
  std::mt19937 rng(11);
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    for (const bool disagree : { false, true })
    {
      AmrHierarchy cells =
        makeSynthetic(seed, options(3, seed % 3 == 0 ? 4 : 2), [](auto&) { return 0.f; });
      // Disagreeing levels: each level adds its own offset (fine wins inside its region).
      AmrHierarchy amr = withPointData(cells,
        [&](const glm::dvec3& p, int level) { return smooth(p) + (disagree ? 0.3 * level : 0.0); });
      const DualMesh mesh = build(amr);
      const GridBox box = amr.domainBox();
      std::uniform_real_distribution<double> u(0.0, 1.0);
      int pairs = 0, straddling = 0, misses = 0;
      double worst = 0.0;
      for (int i = 0; i < 4000; ++i)
      {
        const AmrBlock& block = amr.blocks[rng() % amr.blocks.size()];
        if (block.level == 0)
        {
          continue;
        }
        const double w = double(amr.levelWidth(block.level));
        const int axis = static_cast<int>(rng() % 3);
        const bool upper = (rng() & 1) != 0;
        glm::dvec3 p =
          (glm::dvec3(block.lower) + glm::dvec3(u(rng), u(rng), u(rng)) * glm::dvec3(block.dims)) *
          w;
        p[axis] = (block.lower[axis] + (upper ? block.dims[axis] : 0)) * w;
        glm::dvec3 in = p, out = p;
        in[axis] += upper ? -0.5e-7 : 0.5e-7;
        out[axis] += upper ? 0.5e-7 : -0.5e-7;
        if (out[axis] <= box.lower[axis] || out[axis] >= box.upper[axis])
        {
          continue;
        }
        float a, b;
        SampleHit ha, hb;
        if (!sample(mesh, in, a, &ha) || !sample(mesh, out, b, &hb))
        {
          ++misses;
          continue;
        }
        ++pairs;
        const int la = mesh.gridlets[primIndex(ha.prim)].level;
        const int lb = mesh.gridlets[primIndex(hb.prim)].level;
        straddling += la != lb ? 1 : 0;
        worst = std::max(worst, double(std::abs(a - b)));
      }
      INFO("seed " << seed << (disagree ? " (levels disagree)" : ""));
      CHECK(misses == 0);
      CHECK(straddling > 20);
      CHECK(pairs >= straddling);
      CHECK(worst <= kRelativeTolerance * 2.0); // the field spans about 2 (+0.6)
    }
  }
}

TEST_CASE("a refined cell with every corner on leaves stays empty in the coarse gridlet")
{
  AmrHierarchy amr;
  amr.ratio = { 1, 2 };
  amr.association = FieldAssociation::Points;
  AmrBlock coarse;
  coarse.level = 0;
  coarse.dims = glm::ivec3(4);
  coarse.values.assign(static_cast<std::size_t>(coarse.numPoints()), 1.0f);
  AmrBlock fine;
  fine.level = 1;
  fine.lower = glm::ivec3(2); // refines coarse cell (1, 1, 1) alone
  fine.dims = glm::ivec3(2);
  fine.values.assign(static_cast<std::size_t>(fine.numPoints()), 1.0f);
  fine.values[static_cast<std::size_t>(fine.pointIndex(glm::ivec3(3)))] = 100.0f;      // inside
  fine.values[static_cast<std::size_t>(fine.pointIndex(glm::ivec3(2, 3, 3)))] = 50.0f; // face
  amr.blocks = { coarse, fine };
  const DualMesh mesh = build(amr, 1);
  CHECK(mesh.gridlets.size() > 2); // the coarse block was split around the refined cell
  float v;
  SampleHit hit;
  REQUIRE(sample(mesh, glm::dvec3(3.0), v, &hit)); // the refined cell's centre: fine wins
  CHECK(v == doctest::Approx(100.0f));
  CHECK(mesh.gridlets[primIndex(hit.prim)].level == 1);
  // The face vertex (hanging node of the coarse face) takes the coarse interpolant: 1.
  REQUIRE(sample(mesh, glm::dvec3(2.0, 3.0, 3.0), v));
  CHECK(v == doctest::Approx(1.0f));
  REQUIRE(sample(mesh, glm::dvec3(1.0, 3.0, 3.0), v)); // the coarse neighbour: 1 everywhere
  CHECK(v == doctest::Approx(1.0f));
}

TEST_CASE("the output does not depend on the thread count")
{
  AmrHierarchy cells = makeSynthetic(3, options(3, 2), [](auto&) { return 0.f; });
  AmrHierarchy a = withPointData(cells, [](const glm::dvec3& p, int l) { return smooth(p) + l; });
  AmrHierarchy b = a;
  const DualMesh m1 = build(a, 1), m4 = build(b, 4);
  REQUIRE(m1.gridletScalars.size() == m4.gridletScalars.size());
  CHECK(std::memcmp(m1.gridletScalars.data(),
          m4.gridletScalars.data(),
          m1.gridletScalars.size() * sizeof(float)) == 0);
  REQUIRE(m1.gridlets.size() == m4.gridlets.size());
  CHECK(std::memcmp(m1.gridlets.data(), m4.gridlets.data(), m1.gridlets.size() * 32) == 0);
}

TEST_CASE("non-finite vertices make holes; bad input is refused with a message")
{
  AmrHierarchy cells = makeSynthetic(2, options(2, 2), [](auto&) { return 0.f; });
  AmrHierarchy amr = withPointData(cells, [](const glm::dvec3& p, int) { return p.x; });
  amr.blocks[0].values[0] = std::nanf("");
  amr.validate();
  CHECK(amr.finalizeCellStates() == 1);
  CHECK(amr.blocks[0].state[0] == CellHidden);

  AmrHierarchy wrong = withPointData(cells, [](const glm::dvec3& p, int) { return p.x; });
  wrong.blocks[1].values.pop_back();
  try
  {
    wrong.validate();
    FAIL("a block with one value too few was accepted");
  }
  catch (const std::invalid_argument& e)
  {
    CHECK(std::string(e.what()).find("block 1") != std::string::npos);
    CHECK(std::string(e.what()).find("one per vertex") != std::string::npos);
  }
  AmrHierarchy cellData = cells;
  cellData.validate();
  cellData.finalizeCellStates();
  CHECK_THROWS_WITH_AS(
    buildVertexMesh(cellData), doctest::Contains("holds cell data"), std::invalid_argument);
  AmrHierarchy noStates = withPointData(cells, [](const glm::dvec3& p, int) { return p.x; });
  CHECK_THROWS_WITH_AS(
    buildDualMesh(noStates), doctest::Contains("finalizeCellStates"), std::invalid_argument);
}

TEST_CASE("the memory estimate equals the built mesh's gridlets")
{
  AmrHierarchy cells = makeSynthetic(5, options(3, 2), [](auto&) { return 0.f; });
  AmrHierarchy amr = withPointData(cells, [](const glm::dvec3& p, int) { return smooth(p); });
  const DualMesh mesh = build(amr);
  const DualMeshMemoryEstimate e = estimateDualMeshMemory(amr);
  CHECK(e.mesh.gridletScalars == mesh.memoryReport().gridletScalars);
  CHECK(e.mesh.gridletHeaders == mesh.memoryReport().gridletHeaders);
  CHECK(e.mesh.bvh >= mesh.memoryReport().bvh);
  DualMeshBuildOptions tiny;
  tiny.memoryLimit = 1024;
  CHECK_THROWS_AS(buildDualMesh(amr, tiny), std::length_error);
}
