// The CPU renderer on a synthetic dual mesh (kernel only, no VTK): images are bit-identical for
// 1 and 2 threads, progressive passes accumulate, cancellation keeps per-pixel counts exact,
// depth clipping removes the volume behind it, every integrator runs without majorant
// violations. Set AMRDM_PT_TIMINGS=1 to print 256^2 timings per integrator.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "core/ParallelFor.h"
#include "SyntheticAmr.h"

#include <chrono>
#include <thread>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace amrdm;

namespace
{
DualMesh syntheticMesh(int levels, glm::ivec3 rootCells)
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = levels;
  opt.rootCells = rootCells;
  opt.boxesPerLevel = 4;
  opt.maxBoxCells = 8;
  AmrHierarchy amr = amrdm_test::makeSynthetic(7,
    opt,
    [](const glm::dvec3& p)
    {
      return static_cast<float>(
        0.5 + 0.5 * std::sin(0.15 * p.x) * std::cos(0.2 * p.y) * std::sin(0.1 * p.z + 1.0));
    });
  amr.origin = glm::dvec3(-1.0, 2.0, 0.5);
  amr.finestSpacing = glm::dvec3(0.1, 0.1, 0.12);
  amr.validate();
  amr.finalizeCellStates();
  return buildDualMesh(amr);
}

TransferFunction testTf(float unitDistance)
{
  TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.0f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.1f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.5f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.9f) };
  tf.lo = 0.2f;
  tf.hi = 1.0f;
  tf.unitDistance = unitDistance;
  return tf;
}

RenderParams viewOf(const DualMesh& mesh, int size)
{
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  const glm::vec3 wlo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * lo;
  const glm::vec3 whi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * hi;
  const glm::vec3 centre = 0.5f * (wlo + whi);
  const float radius = 0.5f * glm::length(whi - wlo);
  RenderParams p;
  p.width = p.height = size;
  p.camera.direction = glm::normalize(glm::vec3(-0.4f, -0.3f, -1.0f));
  p.camera.position = centre - p.camera.direction * (radius * 2.5f);
  p.camera.viewAngle = 30.0f;
  p.numLights = 2;
  p.lights[0].direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.5f));
  p.lights[0].intensity = 2.0f;
  p.lights[1].type = LightType::Point;
  p.lights[1].position = centre + glm::vec3(0.0f, radius, 0.0f);
  p.lights[1].intensity = radius * radius;
  p.ambient = glm::vec3(0.3f);
  p.anisotropy = 0.4f;
  return p;
}
} // namespace

TEST_CASE("64x64 renders are bit-identical for 1 and 2 threads, every integrator")
{
  const DualMesh mesh = syntheticMesh(3, glm::ivec3(8, 7, 6));
  for (int integrator = 0; integrator <= 4; ++integrator)
  {
    std::vector<float> images[2];
    for (int t = 0; t < 2; ++t)
    {
      CpuRenderer r;
      r.setMesh(&mesh);
      r.setTransferFunction(testTf(0.2f));
      RenderParams p = viewOf(mesh, 64);
      p.integrator = static_cast<IntegratorType>(integrator);
      p.threads = t + 1;
      p.samplesPerPass = 2;
      p.gradientShading = integrator == 2;
      REQUIRE(r.renderPass(p));
      REQUIRE(r.renderPass(p));
      images[t] = r.image();
      const RenderStats s = r.stats();
      CHECK(s.samples == 64u * 64u * 4u);
      CHECK(s.majorantViolations == 0);
      CHECK(s.stepLimitHits == 0);
    }
    INFO("integrator ", integrator);
    REQUIRE(images[0].size() == 64u * 64u * 4u);
    CHECK(std::memcmp(images[0].data(), images[1].data(), images[0].size() * sizeof(float)) == 0);
    double coverage = 0.0;
    for (std::size_t i = 3; i < images[0].size(); i += 4)
      coverage += images[0][i];
    MESSAGE("integrator ", integrator, ": mean alpha ", coverage / (64.0 * 64.0));
    CHECK(coverage > 0.0);
  }
}

TEST_CASE("cancel() during a pass stops it between tiles; finished tiles keep exact samples")
{
  const DualMesh mesh = syntheticMesh(2, glm::ivec3(6, 6, 6));
  RenderParams p = viewOf(mesh, 192);
  p.integrator = IntegratorType::PathTracer;
  p.samplesPerPass = 8;
  p.tileSize = 16; // 144 tiles: a cancel after the first leaves most of them unstarted
  p.threads = 2;
  CpuRenderer full, cut;
  for (CpuRenderer* r : { &full, &cut })
  {
    r->setMesh(&mesh);
    r->setTransferFunction(testTf(0.1f));
  }
  REQUIRE(full.renderPass(p));

  // Cancel from another thread as soon as the first tile is done (the VTK mapper cancels from
  // the thread that polls vtkRenderWindow::CheckAbortStatus).
  std::thread canceller(
    [&]
    {
      while (cut.tilesDone() == 0)
        std::this_thread::yield();
      cut.cancel();
    });
  const bool completed = cut.renderPass(p);
  canceller.join();
  CHECK_FALSE(completed);
  const std::size_t tiles = (192 / 16) * (192 / 16);
  MESSAGE("cancelled after ", cut.tilesDone(), " of ", tiles, " tiles");
  CHECK(cut.tilesDone() >= 1);
  CHECK(cut.tilesDone() < tiles);

  // Each pixel has all its samples or none, tile by tile; the finished ones equal the
  // uncancelled pass bit for bit (the same random streams).
  const std::vector<float> a = full.image(), b = cut.image();
  std::size_t done = 0, untouched = 0, mismatched = 0;
  for (std::size_t i = 0; i < cut.sampleCounts().size(); ++i)
  {
    const std::uint32_t c = cut.sampleCounts()[i];
    if (c == 8u)
    {
      ++done;
      mismatched += std::memcmp(&a[4 * i], &b[4 * i], 4 * sizeof(float)) != 0;
    }
    else
    {
      untouched += c == 0u;
    }
  }
  CHECK(done + untouched == cut.sampleCounts().size());
  CHECK(done % (16 * 16) == 0);
  CHECK(done == cut.tilesDone() * 16 * 16);
  CHECK(mismatched == 0);

  // The request ended with the pass: the next one runs fully and fills every pixel.
  CHECK(cut.renderPass(p));
  for (std::uint32_t c : cut.sampleCounts())
    CHECK((c == 8u || c == 16u));
}

TEST_CASE("progressive passes, cancellation and depth clipping")
{
  const DualMesh mesh = syntheticMesh(2, glm::ivec3(6, 6, 6));
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(testTf(0.1f));
  RenderParams p = viewOf(mesh, 32);
  p.threads = 2;
  for (int i = 0; i < 4; ++i)
    r.renderPass(p);
  for (std::uint32_t c : r.sampleCounts())
    CHECK(c == 4u);
  const std::vector<float> var = r.varianceOfMean();
  double maxVar = 0.0;
  for (float v : var)
    maxVar = std::max(maxVar, double(v));
  CHECK(maxVar > 0.0);

  // cancel() while no pass runs is dropped (PassCancellation.h): the next pass runs fully.
  r.cancel();
  CHECK(r.renderPass(p));
  for (std::uint32_t c : r.sampleCounts())
    CHECK(c == 5u);

  // Depth 0 everywhere: nothing is visible.
  CpuRenderer clipped;
  clipped.setMesh(&mesh);
  clipped.setTransferFunction(testTf(0.1f));
  std::vector<float> depth(32 * 32, 0.0f);
  clipped.renderPass(p, depth.data());
  for (float v : clipped.image())
    CHECK(v == 0.0f);
}

// Reported as skipped (not passed) unless AMRDM_PT_TIMINGS is set: it prints timings, asserts none.
TEST_CASE("timings of a 256^2 render per integrator (AMRDM_PT_TIMINGS=1)" *
          doctest::skip(std::getenv("AMRDM_PT_TIMINGS") == nullptr))
{
  const DualMesh mesh = syntheticMesh(4, glm::ivec3(16, 16, 16));
  MESSAGE("mesh: ", mesh.counts.toJson());
  const char* names[] = {
    "path tracer", "single scatter", "ray march", "debug primitive", "debug cost"
  };
  for (int integrator = 0; integrator <= 4; ++integrator)
  {
    CpuRenderer r;
    r.setMesh(&mesh);
    r.setTransferFunction(testTf(0.05f));
    RenderParams p = viewOf(mesh, 256);
    p.integrator = static_cast<IntegratorType>(integrator);
    const auto t0 = std::chrono::steady_clock::now();
    constexpr int kPasses = 4;
    for (int i = 0; i < kPasses; ++i)
      r.renderPass(p);
    const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const RenderStats s = r.stats();
    MESSAGE(std::string(names[integrator]),
      ": ",
      ms / kPasses,
      " ms per 1-spp pass (threads ",
      resolveThreadCount(0),
      "), steps/sample ",
      double(s.steps) / double(s.samples),
      ", step-limit hits ",
      s.stepLimitHits,
      ", majorant violations ",
      s.majorantViolations);
    CHECK(s.majorantViolations == 0);
  }
}
