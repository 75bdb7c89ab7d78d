// The renderer suite's CPU cases (TEST_SUITE "cpu", ctest TestCpuRenderer); see TestRenderer.cxx.
#include "TestRendererSuite.h"

using namespace amrdm;
using namespace amrdm::rendertest;

TEST_SUITE("cpu")
{
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

  // Reported as skipped (not passed) unless AMRDM_PT_TIMINGS is set: it prints timings, asserts
  // none.
  TEST_CASE("timings of a 256^2 render per integrator (AMRDM_PT_TIMINGS=1)" *
            doctest::skip(std::getenv("AMRDM_PT_TIMINGS") == nullptr))
  {
    const std::string where = "the CPU (threads " + std::to_string(resolveThreadCount(0)) + ")";
    printTimings<CpuRenderer>(where.c_str(), 256, 0, 4);
  }
} // TEST_SUITE("cpu")
