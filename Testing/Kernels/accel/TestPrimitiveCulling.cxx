// Primitives the transfer function makes invisible cost nothing: with a transfer function that
// is transparent over the lower part of the value range, culling removes primitive tests and
// leaves the image unchanged (the same random numbers make the same decisions).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "SyntheticAmr.h"

#include <cmath>

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
