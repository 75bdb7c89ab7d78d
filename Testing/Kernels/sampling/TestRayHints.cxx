// The tile's ray-hint table (TraceCounters::rayHints, kernel only, no VTK): on synthetic
// hierarchies, neighbouring camera rays marched with the table give the same colour and opacity
// as without it, with fewer primitive tests; a CompositeMedium never hands the region mesh's
// primitives from the table to its proxy.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "accel/MajorantGrid.h"
#include "sampling/CompositeMedium.h"
#include "transport/RayMarcher.h"
#include "SamplingScene.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace amrdm;
using amrdm_test::meshWorldBounds;
using amrdm_test::samplingHierarchy;
using amrdm_test::samplingTf;

namespace
{
/// The scene's medium, counting its primitive tests.
DualMeshMedium countingMedium(const DualMesh& mesh, const TransferFunction& tf)
{
  DualMeshMedium m = amrdm_test::samplingMedium(mesh, tf);
  m.countPrimitiveTests = true;
  return m;
}
} // namespace

TEST_CASE("neighbouring rays with the ray-hint table: the same pixels, fewer primitive tests")
{
  const TransferFunction tf = samplingTf();
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const DualMesh mesh = buildDualMesh(samplingHierarchy(seed));
    const DualMeshMedium medium = countingMedium(mesh, tf);
    MajorantGrid grid = buildMajorantRanges(mesh);
    updateMajorants(grid, tf.view());
    glm::vec3 lo, hi;
    meshWorldBounds(mesh, lo, hi);
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
  const TransferFunction tf = samplingTf();
  const DualMesh region = buildDualMesh(samplingHierarchy(7));
  // The proxy: another hierarchy over the same domain (other primitives, other numbers).
  const DualMesh proxy = buildDualMesh(samplingHierarchy(8));
  CompositeMedium c;
  c.inner = countingMedium(region, tf);
  c.outer = countingMedium(proxy, tf);
  glm::vec3 lo, hi;
  meshWorldBounds(region, lo, hi);
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
