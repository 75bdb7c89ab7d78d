// Primitives the transfer function makes invisible cost nothing: with a transfer function that
// is transparent over the lower part of the value range, culling removes primitive tests and
// leaves the image unchanged (the same random numbers make the same decisions). The ranges are
// kept as 16-bit codes: they hold every value, at any magnitude, and nodes follow their slots.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "SyntheticAmr.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

using namespace amrdm;

TEST_CASE("culling invisible primitives saves work and changes no pixel")
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(12, 10, 8);
  opt.boxesPerLevel = 4;
  AmrHierarchy amr = amrdm_test::makeSynthetic(
    21, opt, [](const glm::dvec3& p) { return static_cast<float>(p.x / 48.0); });
  amr.finalizeCellStates();
  const DualMesh mesh = buildDualMesh(amr);

  TransferFunction tf;
  tf.lo = 0.0f;
  tf.hi = 1.0f;
  tf.unitDistance = 2.0f;
  tf.table.assign(64, glm::vec4(0.9f, 0.8f, 0.7f, 0.0f));
  for (int i = 20; i < 64; ++i)
    tf.table[i].w = 0.6f; // values above ~0.3 are visible

  CpuRenderer renderer;
  renderer.setMesh(&mesh);
  renderer.setTransferFunction(tf);
  const PrimitiveCulling& culling = renderer.primitiveCulling();
  MESSAGE("visible primitive slots: ", culling.visibleSlots, " of ", culling.slotVisible.size());
  CHECK(culling.visibleSlots > 0);
  CHECK(culling.visibleSlots < static_cast<std::int64_t>(culling.slotVisible.size()));

  RenderParams params;
  params.width = params.height = 48;
  params.samplesPerPass = 4;
  params.camera.position = glm::vec3(24.0f, -60.0f, 30.0f);
  params.camera.direction = glm::vec3(0.0f, 1.0f, -0.3f);
  params.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  params.camera.viewAngle = 45.0f;
  params.numLights = 1;
  params.lights[0].direction = glm::vec3(0.3f, -1.0f, 0.8f);

  for (IntegratorType integrator :
    { IntegratorType::PathTracer, IntegratorType::RayMarch, IntegratorType::DebugCost })
  {
    params.integrator = integrator;
    std::vector<float> images[2];
    std::uint64_t tests[2];
    for (int cull = 0; cull < 2; ++cull)
    {
      params.cullInvisiblePrimitives = cull == 1;
      params.integrator = IntegratorType::DebugCost; // counts primitive tests
      renderer.reset();
      renderer.renderPass(params);
      tests[cull] = renderer.stats().primitiveTests;
      params.integrator = integrator;
      renderer.reset();
      renderer.renderPass(params);
      images[cull] = renderer.image();
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i < images[0].size(); ++i)
      differing += std::abs(images[0][i] - images[1][i]) > 1e-6f;
    MESSAGE("integrator ",
      int(integrator),
      ": primitive tests without culling ",
      tests[0],
      ", with culling ",
      tests[1],
      "; differing channels ",
      differing,
      " of ",
      images[0].size());
    CHECK(tests[1] < tests[0]);
    if (integrator != IntegratorType::DebugCost)
      CHECK(differing <= images[0].size() / 1000);
  }
}

TEST_CASE("compact ranges hold every value, widen by at most 2^-7 per end, and nodes OR slots")
{
  // The 16-bit codes are monotonic, and the range read back holds the float it came from, for
  // values across the float range (signs, subnormals, 1e-27 as in a cosmology density).
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::uniform_int_distribution<int> e(-140, 120);
  float previous = -std::numeric_limits<float>::max();
  std::vector<float> values{ 0.0f,
    -0.0f,
    std::numeric_limits<float>::max(),
    -std::numeric_limits<float>::max(),
    std::numeric_limits<float>::denorm_min(),
    1e-27f };
  for (int i = 0; i < 200000; ++i)
    values.push_back(std::ldexp(u(gen), e(gen)));
  std::sort(values.begin(), values.end());
  for (float v : values)
  {
    REQUIRE(rangeLow(rangeCode(v)) <= v);
    REQUIRE(rangeHigh(rangeCode(v)) >= v);
    if (v > previous)
      REQUIRE(rangeCode(v) >= rangeCode(previous)); // monotonic (+0 and -0 differ)
    if (std::fabs(v) >= std::numeric_limits<float>::min() && std::fabs(v) < 1e38f)
    {
      CHECK(rangeHigh(rangeCode(v)) - rangeLow(rangeCode(v)) <= std::fabs(v) / 128.0f);
    }
    previous = v;
  }

  // A mesh of tiny positive values (log-scale data) and a transfer function on log10 of them
  // that is transparent below the middle: the compact ranges still cull, every slot holds its
  // primitive's values, and a node is visible exactly where a slot below it is.
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(10, 9, 8);
  AmrHierarchy amr = amrdm_test::makeSynthetic(
    5, opt, [](const glm::dvec3& p) { return float(1e-27 * std::pow(10.0, p.x / 10.0)); });
  amr.finalizeCellStates();
  const DualMesh mesh = buildDualMesh(amr);
  const PrimitiveCulling built = buildPrimitiveRanges(mesh, 2);
  REQUIRE(built.slotRange.size() == mesh.bvh.prims.size());
  CHECK(built.bytes() == 4 * mesh.bvh.prims.size()); // no masks before a transfer function
  for (std::size_t s = 0; s < mesh.bvh.prims.size(); ++s)
  {
    const std::uint32_t ref = mesh.bvh.prims[s];
    const glm::vec2 r = built.range(s);
    if (primType(ref) == PrimGridlet)
    {
      const GridletHeader& g = mesh.gridlets[primIndex(ref)];
      const std::size_t n = std::size_t(g.dims.x + 1) * (g.dims.y + 1) * (g.dims.z + 1);
      for (std::size_t i = 0; i < n; ++i)
      {
        const float v = mesh.gridletScalars[g.begin + i];
        if (v == v)
          REQUIRE((r.x <= v && v <= r.y));
      }
    }
  }
  TransferFunction tf;
  tf.logScale = true;
  tf.lo = -27.0f;
  tf.hi = -23.0f;
  tf.table.assign(32, glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
  for (int i = 16; i < 32; ++i)
    tf.table[i].w = 0.5f;
  PrimitiveCulling c = built;
  updatePrimitiveVisibility(c, mesh.bvh, tf.view(), 2);
  MESSAGE("log-scale values: visible slots ", c.visibleSlots, " of ", c.slotVisible.size());
  CHECK(c.visibleSlots > 0);
  CHECK(c.visibleSlots < std::int64_t(c.slotVisible.size()));
  CHECK(c.bytes() == 5 * mesh.bvh.prims.size() + mesh.bvh.nodes.size());
  // Node visibility against a brute-force walk of each subtree.
  std::function<bool(std::uint32_t)> anyVisible = [&](std::uint32_t node) -> bool
  {
    const BvhNode& n = mesh.bvh.nodes[node];
    if (n.count == 0)
      return anyVisible(n.first) || anyVisible(n.first + 1);
    for (std::uint32_t k = 0; k < n.count; ++k)
      if (c.slotVisible[n.first + k])
        return true;
    return false;
  };
  std::size_t hidden = 0;
  for (std::uint32_t i = 0; i < mesh.bvh.nodes.size(); ++i)
  {
    REQUIRE(bool(c.nodeVisible[i]) == anyVisible(i));
    hidden += !c.nodeVisible[i];
  }
  CHECK(hidden > 0);
}
