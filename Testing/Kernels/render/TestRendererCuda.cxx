// The renderer suite's CUDA cases (TEST_SUITE "cuda", ctest TestCudaRenderer, CUDA builds); see
// TestRenderer.cxx.
#include "TestRendererSuite.h"

#ifdef AMRDM_TEST_CUDA
using namespace amrdm;
using namespace amrdm::rendertest;

TEST_SUITE("cuda")
{
  // --- Device-free cases (run with or without a GPU) -----------------------------------------

  TEST_CASE("device choice: cpu, auto and cuda")
  {
    std::vector<std::string> lines;
    const RendererLog log = [&](const std::string& line) { lines.push_back(line); };
    CHECK(createRenderer(RenderDevice::Cpu, log)->device() == RenderDevice::Cpu);
    CHECK(lines.empty());

    const std::unique_ptr<Renderer> autoRenderer = createRenderer(RenderDevice::Auto, log);
    REQUIRE(lines.size() == 1); // said once
    MESSAGE("auto: ", lines[0]);
    CHECK(autoRenderer->device() == (gHaveDevice ? RenderDevice::Cuda : RenderDevice::Cpu));
    CHECK(lines[0].find(gHaveDevice ? "CUDA device" : "on the CPU") != std::string::npos);

    if (gHaveDevice)
    {
      CHECK(createRenderer(RenderDevice::Cuda, log)->device() == RenderDevice::Cuda);
    }
    else
    {
      std::string message;
      try
      {
        createRenderer(RenderDevice::Cuda, log);
      }
      catch (const std::runtime_error& e)
      {
        message = e.what();
      }
      MESSAGE("cuda: ", message);
      CHECK(message.find("CUDA rendering was requested, but") == 0);
      CHECK(message.find(gNoDeviceReason) != std::string::npos);
    }
    RenderDevice d;
    CHECK((parseRenderDevice("cuda", d) && d == RenderDevice::Cuda));
    CHECK(!parseRenderDevice("gpu", d));
  }

  TEST_CASE("amrdm-render --device cpu|auto|cuda")
  {
    if (gRenderApp.empty())
    {
      MESSAGE("no amrdm-render path given: skipped");
      return;
    }
    const std::string base = "\"" + gRenderApp + "\" --size 24 24 --spp 2 ";
    std::string out;
    CHECK(runCommand(base + "--device cpu", out) == 0);
    CHECK(out.find("cpu: 24x24") != std::string::npos);
    CHECK(out.find("device auto") == std::string::npos);

    CHECK(runCommand(base + "--device auto", out) == 0);
    CHECK(countOccurrences(out, "amrdm-render: device auto: rendering on") == 1);
    CHECK(out.find(gHaveDevice ? "cuda: 24x24" : "cpu: 24x24") != std::string::npos);
    MESSAGE("--device auto:\n", out);

    const int rc = runCommand(base + "--device cuda", out);
    MESSAGE("--device cuda (exit ", rc, "):\n", out);
    if (gHaveDevice)
    {
      CHECK(rc == 0);
      CHECK(out.find("cuda: 24x24") != std::string::npos);
      CHECK(out.find("gpu memory: {") != std::string::npos);
    }
    else
    {
      CHECK(rc != 0);
      CHECK(out.find("amrdm-render: CUDA rendering was requested, but " + gNoDeviceReason) !=
            std::string::npos);
    }

    CHECK(runCommand(base + "--device gpu", out) != 0);
    CHECK(out.find("--device: expected auto, cpu or cuda, got 'gpu'") != std::string::npos);
    CHECK(runCommand(base + "--device cpu --fps-frames 12 --size 16 16", out) == 0);
    CHECK(out.find("fps: cpu 16x16, mean of frames 11..12:") != std::string::npos);
  }

  // --- Device cases ------------------------------------------------------------------------

  TEST_CASE("device: CPU and GPU images agree statistically, every integrator")
  {
    const DualMesh mesh = syntheticMesh(3, glm::ivec3(8, 7, 6));
    const char* names[] = {
      "path tracer", "single scatter", "ray march", "debug primitive", "debug cost"
    };
    for (int integrator = 0; integrator <= 4; ++integrator)
    {
      RenderParams p = viewOf(mesh, 48);
      p.integrator = static_cast<IntegratorType>(integrator);
      p.gradientShading = integrator == 2;
      p.samplesPerPass = 16;
      constexpr int kPasses = 4; // 64 spp, accumulated over passes

      CpuRenderer cpu;
      cpu.setMesh(&mesh);
      cpu.setTransferFunction(testTf(0.2f));
      CudaRenderer gpu;
      gpu.setMesh(&mesh);
      gpu.setTransferFunction(testTf(0.2f));
      CudaRenderer gpuSameSeed;
      gpuSameSeed.setMesh(&mesh);
      gpuSameSeed.setTransferFunction(testTf(0.2f));
      RenderParams q = p;
      q.seed = 12345; // independent random streams for the statistical comparison
      for (int i = 0; i < kPasses; ++i)
      {
        REQUIRE(cpu.renderPass(p));
        REQUIRE(gpu.renderPass(q));
        REQUIRE(gpuSameSeed.renderPass(p));
      }
      const std::vector<float> a = cpu.image(), va = cpu.varianceOfMean();
      const std::vector<float> b = gpu.image(), vb = gpu.varianceOfMean();
      const std::vector<float> c = gpuSameSeed.image();
      REQUIRE(b.size() == a.size());
      double worstZ = 0.0;
      const double agree = agreeingPixels(a, va, b, vb, 1e-4, &worstZ);
      // The same random streams: most pixels should match to rounding (FMA contraction and
      // library maths differ, so a path may occasionally take another branch).
      std::size_t same = 0;
      for (std::size_t i = 0; i < a.size(); i += 4)
      {
        bool eq = true;
        for (int k = 0; k < 4; ++k)
          eq = eq && std::fabs(a[i + k] - c[i + k]) <= 1e-4f * (1.0f + std::fabs(a[i + k]));
        same += eq;
      }
      const RenderStats cs = cpu.stats(), gs = gpu.stats();
      MESSAGE(names[integrator],
        ": ",
        100.0 * agree,
        "% of pixels agree (worst z ",
        worstZ,
        "), same seed: ",
        100.0 * double(same) / double(a.size() / 4),
        "% equal to 1e-4; steps/sample CPU ",
        double(cs.steps) / double(cs.samples),
        " GPU ",
        double(gs.steps) / double(gs.samples));
      CHECK(agree >= 0.99);
      CHECK(gs.samples == 48u * 48u * 64u);
      CHECK(gs.passes == kPasses);
      CHECK(gs.majorantViolations == 0);
      CHECK(gs.stepLimitHits == 0);
      for (std::uint32_t n : gpu.sampleCounts())
        CHECK(n == 64u);
    }
  }

  // DistributionMode Proxy on the device: the region's mesh inside its box, a proxy of the whole
  // domain outside it (here a one-level mesh of the same domain), over the composite majorant grid;
  // the integrators that scatter see it (RenderScene::seesProxy), as CpuRenderer::setProxy does.
  TEST_CASE("device: the proxy medium agrees with the CPU's, path tracer and single scatter")
  {
    const DualMesh mesh = syntheticMesh(3, glm::ivec3(8, 7, 6));
    const DualMesh proxy = syntheticMesh(1, glm::ivec3(8, 7, 6) * 4); // ratio 2, 3 levels
    glm::vec3 glo, ghi;
    mesh.gridBounds(glo, ghi);
    const glm::vec3 wlo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * glo;
    const glm::vec3 whi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * ghi;
    const glm::vec3 boxHi(0.5f * (wlo.x + whi.x), whi.y, whi.z); // the region: half the domain
    for (IntegratorType integrator : { IntegratorType::PathTracer, IntegratorType::SingleScatter })
    {
      RenderParams p = viewOf(mesh, 40);
      p.integrator = integrator;
      p.samplesPerPass = 16;
      p.clipToBox = true;
      p.clipLo = wlo;
      p.clipHi = boxHi;
      CpuRenderer cpu;
      CudaRenderer gpu;
      for (Renderer* r : { static_cast<Renderer*>(&cpu), static_cast<Renderer*>(&gpu) })
      {
        r->setMesh(&mesh);
        r->setTransferFunction(testTf(0.2f));
        r->setProxy(&proxy, wlo, boxHi);
      }
      REQUIRE(!gpu.scene().compositeMajorantGrid().majorant.empty());
      RenderParams q = p;
      q.seed = 777; // independent streams
      for (int i = 0; i < 4; ++i)
      {
        REQUIRE(cpu.renderPass(p));
        REQUIRE(gpu.renderPass(q));
      }
      double worstZ = 0.0;
      const double agree = agreeingPixels(
        cpu.image(), cpu.varianceOfMean(), gpu.image(), gpu.varianceOfMean(), 1e-4, &worstZ);
      MESSAGE(integratorInfo(integrator).name,
        " with the proxy: ",
        100.0 * agree,
        "% of pixels agree (worst z ",
        worstZ,
        ")");
      CHECK(agree >= 0.99);
      CHECK(gpu.stats().majorantViolations == 0);
      // Clearing the proxy goes back to the region alone.
      gpu.setProxy(nullptr, glm::vec3(0.0f), glm::vec3(0.0f));
      CHECK(gpu.scene().compositeMajorantGrid().majorant.empty());
      CHECK(gpu.renderPass(p));
    }
  }

  TEST_CASE("device: depth clipping, minimum distance, reset, size change")
  {
    const DualMesh mesh = syntheticMesh(2, glm::ivec3(6, 6, 6));
    CudaRenderer r;
    r.setMesh(&mesh);
    r.setTransferFunction(testTf(0.1f));
    RenderParams p = viewOf(mesh, 32);
    std::vector<float> depth(32 * 32, 0.0f);
    REQUIRE(r.renderPass(p, depth.data()));
    for (float v : r.image())
      CHECK(v == 0.0f);
    r.reset();
    std::vector<float> far(32 * 32, kInfinity), start(32 * 32, 1e9f);
    REQUIRE(r.renderPass(p, far.data(), start.data())); // minT beyond everything: empty
    for (float v : r.image())
      CHECK(v == 0.0f);
    // Depth clipping equals the CPU's on the same streams: compare coverage means.
    r.reset();
    CpuRenderer cpu;
    cpu.setMesh(&mesh);
    cpu.setTransferFunction(testTf(0.1f));
    glm::vec3 lo, hi;
    mesh.gridBounds(lo, hi);
    const float radius = 0.5f * glm::length(glm::vec3(mesh.finestSpacing) * (hi - lo));
    std::vector<float> half(32 * 32, 2.5f * radius); // the camera's distance to the centre
    p.samplesPerPass = 32;
    REQUIRE(r.renderPass(p, half.data()));
    REQUIRE(cpu.renderPass(p, half.data()));
    double worstZ = 0.0;
    CHECK(
      agreeingPixels(
        cpu.image(), cpu.varianceOfMean(), r.image(), r.varianceOfMean(), 1e-4, &worstZ) >= 0.99);
    // A size change reallocates and clears.
    p.width = 20;
    p.height = 10;
    p.samplesPerPass = 1;
    REQUIRE(r.renderPass(p));
    const std::vector<std::uint32_t> counts = r.sampleCounts();
    CHECK(counts.size() == 200u);
    for (std::uint32_t n : counts)
      CHECK(n == 1u);
  }

  TEST_CASE(
    "device: memory report, computed vs measured; a transfer function re-uploads only its part")
  {
    const DualMesh mesh = syntheticMesh(4, glm::ivec3(16, 16, 16));
    CudaRenderer r;
    r.setMesh(&mesh);
    r.setTransferFunction(testTf(0.05f));
    RenderParams p = viewOf(mesh, 256);
    REQUIRE(r.renderPass(p));
    const GpuMemoryReport before = r.memoryReport();
    MESSAGE("memory report: ", before.toJson());
    const MemoryReport host = mesh.memoryReport();
    auto computed = [&](const GpuMemoryReport& rep, const char* name)
    {
      const GpuMemoryReport::Entry* e = rep.find(name);
      REQUIRE(e != nullptr);
      return e->computed;
    };
    CHECK(computed(before, "gridletScalars") == host.gridletScalars);
    CHECK(computed(before, "gridletHeaders") ==
          host.gridletHeaders + mesh.levelWidth.size() * sizeof(float));
    CHECK(computed(before, "elementVertices") == host.elementVertices);
    CHECK(computed(before, "elementIndices") == host.elementIndices);
    CHECK(computed(before, "bvh") == host.bvh);
    CHECK(computed(before, "majorantGrid") ==
          (r.majorantGrid().majorant.size() + r.majorantGrid().cellWidth.size()) * sizeof(float));
    CHECK(computed(before, "cullingMasks") ==
          r.primitiveCulling().slotVisible.size() + r.primitiveCulling().nodeVisible.size());
    CHECK(computed(before, "transferFunction") == testTf(0.05f).table.size() * 16u);
    CHECK(computed(before, "frameBuffers") == 256u * 256u * kAccumulationBytesPerPixel); // 68 B
    // Measured: the driver allocates in pages (2 MiB) and may place small buffers in pages it
    // already holds, so per category it may be 0 or round up; the total stays near our count.
    const double mib = 1024.0 * 1024.0;
    const std::int64_t allocations = 20; // device buffers of a renderer
    CHECK(double(before.measuredTotal()) >= double(before.computedTotal()) - 2.0 * mib);
    CHECK(double(before.measuredTotal()) <=
          double(before.computedTotal()) + (allocations + 1) * 2.0 * mib);
    for (const GpuMemoryReport::Entry& e : before.entries)
      CHECK(e.measured >= 0);

    // A new transfer function (same table size) reallocates nothing: every figure is unchanged.
    TransferFunction tf2 = testTf(0.5f);
    tf2.table[1].w = 0.0f;
    r.setTransferFunction(tf2);
    const GpuMemoryReport after = r.memoryReport();
    for (std::size_t i = 0; i < before.entries.size(); ++i)
    {
      INFO(before.entries[i].category);
      CHECK(after.entries[i].computed == before.entries[i].computed);
      CHECK(after.entries[i].measured == before.entries[i].measured);
    }
  }

  TEST_CASE("device: out of memory is a clear error; auto falls back to the CPU")
  {
    const DualMesh mesh = syntheticMesh(3, glm::ivec3(8, 7, 6));
    CudaRenderer limited;
    limited.setMemoryLimit(1024);
    std::string message;
    try
    {
      limited.setMesh(&mesh);
    }
    catch (const GpuOutOfMemory& e)
    {
      message = e.what();
    }
    MESSAGE("out of memory: ", message);
    CHECK(message.find("CUDA: out of device memory allocating ") == 0);

    std::vector<std::string> lines;
    std::unique_ptr<CudaRenderer> gpu(new CudaRenderer);
    gpu->setMemoryLimit(1024);
    std::unique_ptr<Renderer> fallbackPtr =
      withCpuFallback(std::move(gpu), [&](const std::string& line) { lines.push_back(line); });
    Renderer& fallback = *fallbackPtr;
    CHECK(fallback.device() == RenderDevice::Cuda);
    fallback.setMesh(&mesh, glm::ivec3(0), 0);
    fallback.setTransferFunction(testTf(0.2f), 0);
    CHECK(fallback.device() == RenderDevice::Cpu);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].find("falling back to the CPU renderer") != std::string::npos);
    RenderParams p = viewOf(mesh, 32);
    REQUIRE(fallback.renderPass(p, nullptr, nullptr));
    CpuRenderer cpu;
    cpu.setMesh(&mesh);
    cpu.setTransferFunction(testTf(0.2f));
    REQUIRE(cpu.renderPass(p));
    CHECK(fallback.image() == cpu.image());
  }

  // Reported as skipped (not passed) unless AMRDM_CUDA_TIMINGS is set: it prints timings, asserts
  // none.
  TEST_CASE("device: timings of a 1024^2 1-spp pass per integrator (AMRDM_CUDA_TIMINGS=1)" *
            doctest::skip(std::getenv("AMRDM_CUDA_TIMINGS") == nullptr))
  {
    const std::string where = CudaRenderer().deviceName();
    printTimings<CudaRenderer>(where.c_str(), 1024, 10, 100);
  }
} // TEST_SUITE("cuda")
#endif
