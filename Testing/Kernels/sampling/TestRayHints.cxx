// The tile's ray-hint table (TraceCounters::rayHints, kernel only, no VTK): on synthetic
// hierarchies, neighbouring camera rays marched with the table give the same colour and opacity
// as without it, with fewer primitive tests; a CompositeMedium never hands the region mesh's
// primitives from the table to its proxy.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "accel/MajorantGrid.h"
#include "mesh/DualMeshBuilder.h"
#include "sampling/CompositeMedium.h"
#include "transport/RayMarcher.h"
#include "SyntheticAmr.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace amrdm;

namespace
{
float field(const glm::dvec3& p)
{
  return static_cast<float>(
    0.5 + 0.5 * std::sin(0.21 * p.x) * std::cos(0.17 * p.y) * std::sin(0.13 * p.z + 0.4));
}

AmrHierarchy synthetic(unsigned seed)
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(10, 9, 8);
  opt.boxesPerLevel = 4;
  opt.maxBoxCells = 8;
  AmrHierarchy amr = amrdm_test::makeSynthetic(seed, opt, field);
  amr.origin = glm::dvec3(0.5, -1.0, 2.0);
  amr.finestSpacing = glm::dvec3(0.1, 0.11, 0.1);
  amr.validate();
  amr.finalizeCellStates();
  return amr;
}

TransferFunction testTf()
{
  TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.05f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.3f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.6f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.9f) };
  tf.lo = 0.0f;
  tf.hi = 1.0f;
  tf.unitDistance = 0.5f;
  return tf;
}

DualMeshMedium mediumOf(const DualMesh& mesh, const TransferFunction& tf)
{
  DualMeshMedium m;
  m.mesh = mesh.view();
  m.tf = tf.view();
  m.origin = glm::vec3(mesh.origin);
  m.invSpacing = glm::vec3(1.0 / mesh.finestSpacing);
  m.countPrimitiveTests = true;
  return m;
}

void worldBounds(const DualMesh& mesh, glm::vec3& lo, glm::vec3& hi)
{
  glm::vec3 glo, ghi;
  mesh.gridBounds(glo, ghi);
  lo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * glo;
  hi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * ghi;
}
} // namespace

TEST_CASE("neighbouring rays with the ray-hint table: the same pixels, fewer primitive tests")
{
  const TransferFunction tf = testTf();
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const DualMesh mesh = buildDualMesh(synthetic(seed));
    const DualMeshMedium medium = mediumOf(mesh, tf);
    MajorantGrid grid = buildMajorantRanges(mesh);
    updateMajorants(grid, tf.view());
    glm::vec3 lo, hi;
    worldBounds(mesh, lo, hi);
    RenderParams params;
    params.stepSize = 0.37f * float(mesh.finestSpacing.x) * (1.0f + 0.1f * float(seed));
    // A 40 x 40 fan of rays from one eye, in the tile loop's order (rows of neighbours).
    const glm::vec3 centre = 0.5f * (lo + hi);
    const glm::vec3 eye = centre + glm::vec3(-1.1f, -0.6f, -1.7f) * glm::length(hi - lo);
    const glm::vec3 forward = glm::normalize(centre - eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    std::vector<std::uint32_t> table(kRayHintSlots, ~0u);
    TraceCounters plain, hinted;
    hinted.rayHints = table.data();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int covered = 0;
    const int n = 40;
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x)
      {
        Ray ray;
        ray.o = eye;
        ray.d = glm::normalize(forward + 0.4f * ((float(x) + 0.5f) / n - 0.5f) * right +
                               0.4f * ((float(y) + 0.5f) / n - 0.5f) * up);
        const float jitter = u(rng);
        plain.lastPrimitive = hinted.lastPrimitive = ~0u; // as renderSampleWith()
        const SampleResult a = rayMarch(medium, grid.view(), params, ray, kInfinity, jitter, plain);
        const SampleResult b =
          rayMarch(medium, grid.view(), params, ray, kInfinity, jitter, hinted);
        REQUIRE_MESSAGE(a.alpha == b.alpha, "seed ", seed, " pixel ", x, ",", y);
        REQUIRE(a.L.x == b.L.x);
        REQUIRE(a.L.y == b.L.y);
        REQUIRE(a.L.z == b.L.z);
        REQUIRE(hinted.hintSlot == ~0u); // no slot outlives its sample
        covered += a.alpha > 0.0f ? 1 : 0;
      }
    }
    REQUIRE(plain.steps == hinted.steps);
    MESSAGE("seed ",
      seed,
      ": ",
      covered,
      " covered pixels, ",
      plain.steps,
      " samples, ",
      plain.primitiveTests,
      " primitive tests without the table, ",
      hinted.primitiveTests,
      " with it");
    CHECK(covered > n * n / 4);
    CHECK(hinted.primitiveTests < plain.primitiveTests);
    CHECK(std::count(table.begin(), table.end(), ~0u) < int(kRayHintSlots));
  }
}

TEST_CASE("a composite medium never tests the table's region primitives in its proxy")
{
  const TransferFunction tf = testTf();
  const AmrHierarchy amr = synthetic(7);
  const DualMesh region = buildDualMesh(amr);
  // The proxy: another hierarchy over the same domain (other primitives, other numbers).
  const DualMesh proxy = buildDualMesh(synthetic(8));
  CompositeMedium c;
  c.inner = mediumOf(region, tf);
  c.outer = mediumOf(proxy, tf);
  glm::vec3 lo, hi;
  worldBounds(region, lo, hi);
  c.lo = lo + 0.25f * (hi - lo);
  c.hi = lo + 0.5f * (hi - lo);
  std::vector<std::uint32_t> table(kRayHintSlots, ~0u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int outside = 0;
  for (int i = 0; i < 4000; ++i)
  {
    const glm::vec3 p = lo + (hi - lo) * glm::vec3(u(rng), u(rng), u(rng));
    // Every slot holds a primitive of the region mesh (or none) from an earlier inside sample.
    TraceCounters counters;
    counters.rayHints = table.data();
    counters.hintSlot = std::uint32_t(i) & (kRayHintSlots - 1);
    const std::vector<std::uint32_t> before = table;
    float got = -1.0f, expected = -2.0f;
    const bool has = c.value(p, got, counters);
    TraceCounters fresh;
    const bool in = c.inside(p);
    const bool exp = in ? c.inner.value(p, expected, fresh) : c.outer.value(p, expected, fresh);
    REQUIRE(has == exp);
    if (has)
    {
      REQUIRE(got == expected);
    }
    REQUIRE(counters.hintSlot == (std::uint32_t(i) & (kRayHintSlots - 1)));
    if (!in)
    {
      ++outside;
      REQUIRE(table == before); // the proxy's lookups leave the region's hints alone
    }
  }
  CHECK(outside > 1000);
}
