// The region-plus-proxy medium of DistributionMode Proxy (kernel only, no VTK): on synthetic
// hierarchies split by the kd-tree partition, CompositeMedium answers with the region's exact
// mesh inside the region's box and with the level-0 proxy outside it; the two meshes' "previous
// primitive" hints never mix; the composite majorant grid bounds every sampled extinction
// (random points and points on the box's faces); CpuRenderer::setProxy renders with it without
// a majorant violation, changes what scattered light sees, and refuses an empty box.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "accel/CompositeMajorantGrid.h"
#include "mesh/DomainPartition.h"
#include "mesh/DualMeshBuilder.h"
#include "render/CpuRenderer.h"
#include "sampling/CompositeMedium.h"
#include "SamplingScene.h"

#include <cmath>
#include <random>
#include <stdexcept>

using namespace amrdm;
using amrdm_test::meshWorldBounds;
using amrdm_test::samplingMedium;
using amrdm_test::samplingTf;

namespace
{
/// Level 0 alone, in level-0 units (what AssembleCoarse hands the mapper).
AmrHierarchy levelZero(const AmrHierarchy& amr)
{
  AmrHierarchy coarse;
  coarse.ratio = { 1 };
  coarse.origin = amr.origin;
  coarse.finestSpacing = amr.finestSpacing * double(amr.levelWidth(0));
  for (const AmrBlock& b : amr.blocks)
  {
    if (b.level == 0)
    {
      AmrBlock c = b;
      c.state.clear();
      coarse.blocks.push_back(c);
    }
  }
  coarse.validate();
  coarse.finalizeCellStates();
  return coarse;
}

struct Scene
{
  AmrHierarchy amr;
  DualMesh region, proxy;
  glm::vec3 lo, hi; ///< region box, scene frame
};

Scene makeScene(unsigned seed, int regionIndex)
{
  Scene s;
  s.amr = amrdm_test::samplingHierarchy(seed);
  const DomainPartition partition = partitionDomain(s.amr, 2);
  s.region = buildDualMesh(regionHierarchy(s.amr, partition.regions[regionIndex]));
  s.proxy = buildDualMesh(levelZero(s.amr));
  glm::dvec3 glo, ghi;
  partition.gridBox(s.amr, regionIndex, glo, ghi);
  s.lo = glm::vec3(s.amr.origin + s.amr.finestSpacing * glo);
  s.hi = glm::vec3(s.amr.origin + s.amr.finestSpacing * ghi);
  return s;
}
} // namespace

TEST_CASE("inside the box the region's mesh answers, outside the proxy; hints never mix")
{
  const TransferFunction tf = samplingTf();
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const Scene s = makeScene(seed, int(seed % 2));
    CompositeMedium c;
    c.inner = samplingMedium(s.region, tf);
    c.outer = samplingMedium(s.proxy, tf);
    c.lo = s.lo;
    c.hi = s.hi;
    glm::vec3 wlo, whi;
    meshWorldBounds(s.proxy, wlo, whi);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    TraceCounters shared; // carried over every point, as along a path
    int inside = 0, outside = 0;
    for (int i = 0; i < 4000; ++i)
    {
      const glm::vec3 p = wlo + (whi - wlo) * glm::vec3(u(rng), u(rng), u(rng));
      TraceCounters fresh;
      float got = -1.0f, expected = -2.0f;
      const bool has = c.value(p, got, shared);
      const bool in = c.inside(p);
      const bool exp = in ? c.inner.value(p, expected, fresh) : c.outer.value(p, expected, fresh);
      REQUIRE(has == exp);
      if (has)
      {
        REQUIRE(got == expected);
      }
      (in ? inside : outside) += 1;
    }
    MESSAGE("seed ", seed, ": ", inside, " points inside the box, ", outside, " outside");
    CHECK(inside > 100);
    CHECK(outside > 100);
  }
}

TEST_CASE("the composite majorant grid bounds every sampled extinction")
{
  const TransferFunction tf = samplingTf();
  long long points = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    const Scene s = makeScene(seed, int(seed % 2));
    MajorantGrid inner = buildMajorantRanges(s.region);
    glm::vec3 wlo, whi;
    meshWorldBounds(s.proxy, wlo, whi);
    const glm::ivec3 res = compositeMajorantResolution(inner, wlo, whi);
    const MajorantGrid outer = buildMajorantRanges(s.proxy, res);
    MajorantGrid grid = compositeMajorantRanges(outer, inner, s.lo, s.hi);
    updateMajorants(grid, tf.view());
    CompositeMedium c;
    c.inner = samplingMedium(s.region, tf);
    c.outer = samplingMedium(s.proxy, tf);
    c.lo = s.lo;
    c.hi = s.hi;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    TraceCounters counters;
    for (int i = 0; i < 20000; ++i)
    {
      glm::vec3 p = wlo + (whi - wlo) * glm::vec3(u(rng), u(rng), u(rng));
      if (i % 3 == 0)
      {
        const int axis = int(rng() % 3u);
        p[axis] = (rng() % 2u) ? s.lo[axis] : s.hi[axis]; // on a face of the box
      }
      const float sigma = c.sample(p, counters).sigmaT;
      REQUIRE_MESSAGE(sigma <= majorantAt(grid.view(), p), "seed ", seed, " point ", i);
      ++points;
    }
  }
  MESSAGE(points, " points checked");
  // Bad input is named.
  CHECK_THROWS_AS(
    compositeMajorantRanges(MajorantGrid(), MajorantGrid(), glm::vec3(0.0f), glm::vec3(1.0f)),
    std::invalid_argument);
}

TEST_CASE("CpuRenderer with a proxy: scattered light sees it, no majorant violation")
{
  const Scene s = makeScene(3, 0);
  glm::vec3 wlo, whi;
  meshWorldBounds(s.proxy, wlo, whi);
  const glm::vec3 centre = 0.5f * (wlo + whi);
  const float radius = 0.5f * glm::length(whi - wlo);
  RenderParams p;
  p.width = p.height = 48;
  p.integrator = IntegratorType::SingleScatter;
  p.camera.direction = glm::normalize(glm::vec3(-0.4f, -0.3f, -1.0f));
  p.camera.position = centre - p.camera.direction * (radius * 2.5f);
  p.camera.viewAngle = 30.0f;
  p.numLights = 1;
  // The light comes through the other region: without the proxy it is unshadowed.
  p.lights[0].direction = glm::normalize(glm::vec3(1.0f, 0.2f, 0.1f));
  p.lights[0].intensity = 2.0f;
  p.ambient = glm::vec3(0.0f);
  p.clipToBox = true;
  p.clipLo = s.lo;
  p.clipHi = s.hi;
  p.samplesPerPass = 8;
  double sums[2] = { 0.0, 0.0 };
  for (int withProxy = 0; withProxy < 2; ++withProxy)
  {
    CpuRenderer r;
    r.setMesh(&s.region);
    r.setTransferFunction(samplingTf());
    if (withProxy)
    {
      r.setProxy(&s.proxy, s.lo, s.hi);
      CHECK(!r.compositeMajorantGrid().majorant.empty());
    }
    REQUIRE(r.renderPass(p));
    CHECK(r.stats().majorantViolations == 0);
    for (float v : r.image())
    {
      sums[withProxy] += v;
    }
    // Clearing the proxy goes back to the region alone.
    r.setProxy(nullptr, glm::vec3(0.0f), glm::vec3(0.0f));
    CHECK(r.compositeMajorantGrid().majorant.empty());
  }
  MESSAGE("image sums: region alone ", sums[0], ", with the proxy ", sums[1]);
  CHECK(sums[0] > 0.0);
  CHECK(sums[1] < 0.97 * sums[0]); // the other region's shadow
  CpuRenderer r;
  r.setMesh(&s.region);
  CHECK_THROWS_AS(r.setProxy(&s.proxy, s.hi, s.lo), std::invalid_argument);
}
