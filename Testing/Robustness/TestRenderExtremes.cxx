// Rendering extremes of the transport (kernel only, no VTK), each against an independent
// expectation: fully transparent / fully opaque / single-spike transfer functions, density
// scales 1e-6 .. 1e6 (quadrature of the field along each pixel's ray, bounded work per sample)
// and 0 .. 1024 bounces. Camera, image-size and sample-count extremes: TestRenderExtremesImage.
// Numbers are printed with MESSAGE; docs/ROBUSTNESS.md lists them.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RenderExtremes.h"

#include <chrono>
#include <cstring>

using namespace amrdm;
using namespace amrdm_test;

TEST_CASE("fully transparent transfer function: background exactly, no density work")
{
  const DualMesh mesh = twoLevelMesh();
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(table(
    { glm::vec4(1.0f, 0.5f, 0.2f, 0.0f), glm::vec4(0.3f, 0.9f, 0.1f, 0.0f) }, 0.0f, 1.0f, 1e-4f));
  for (float m : r.majorantGrid().majorant)
    REQUIRE(m == 0.0f);
  CHECK(r.primitiveCulling().visibleSlots == 0);
  for (int integrator = 0; integrator <= 5; ++integrator)
  {
    RenderParams p = view(mesh, 32);
    p.integrator = static_cast<IntegratorType>(std::min(integrator, 4));
    p.gradientShading = integrator == 5; // ray marching with gradients: culling off
    p.integrator = integrator == 5 ? IntegratorType::RayMarch : p.integrator;
    p.samplesPerPass = 2;
    r.reset();
    REQUIRE(r.renderPass(p));
    const RenderStats s = r.stats();
    INFO("integrator ", integrator);
    CHECK(s.steps == 0);
    CHECK(s.primitiveTests == 0);
    const std::vector<float> img = r.image();
    REQUIRE(img.size() == 32u * 32u * 4u);
    for (std::size_t i = 0; i < img.size(); ++i) // the cost view paints black at cost 0
      REQUIRE(img[i] == (integrator == 4 && i % 4 == 3 ? 1.0f : 0.0f));
  }
}

TEST_CASE("fully opaque transfer function: coverage 1 wherever the data is crossed")
{
  const DualMesh mesh = twoLevelMesh();
  const TransferFunction tf = table({ glm::vec4(0.7f, 0.5f, 0.3f, 1.0f) }, 0.0f, 1.0f, 1e-3f);
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(tf);
  RenderParams p = view(mesh, 32);
  p.samplesPerPass = 4;
  std::vector<double> tau(32 * 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      tau[y * 32 + x] = integrate(mesh, tf, p, x, y, 2000).tau;
  for (IntegratorType it : { IntegratorType::PathTracer, IntegratorType::RayMarch })
  {
    p.integrator = it;
    r.reset();
    r.renderPass(p);
    const std::vector<float> img = r.image();
    CHECK(allFinite(img));
    CHECK(r.stats().majorantViolations == 0);
    CHECK(r.stats().stepLimitHits == 0);
    int opaque = 0;
    // Opaque: tau > 40 (path tracer), and for ray marching a chord of more than 2 steps.
    const double sigma = tfExtinction(tf.view(), 0.5f), step = 0.5 * mesh.finestSpacing.x;
    const double threshold = it == IntegratorType::RayMarch ? 2.0 * step * sigma : 40.0;
    for (std::size_t i = 0; i < tau.size(); ++i)
    {
      const float a = img[4 * i + 3];
      CHECK((a >= 0.0f && a <= 1.0f));
      if (tau[i] > threshold)
      {
        ++opaque;
        CHECK(a >= (it == IntegratorType::RayMarch ? 0.99f : 1.0f));
        CHECK(img[4 * i] <= a * 0.7f + 1e-6f); // ray marching: colour = albedo x alpha
      }
    }
    MESSAGE("opaque pixels ", opaque);
    CHECK(opaque > 500);
    if (it == IntegratorType::PathTracer)
      checkCoverage(r, tau, 1.0, 2e-3);
  }
}

TEST_CASE("a single-spike transfer function: conservative majorants, the spike is seen")
{
  // Non-zero only for values in [0.55 - 2e-3, 0.55 + 2e-3] (0.4% of the field's range).
  const DualMesh mesh = twoLevelMesh();
  const float v0 = 0.55f, w = 2e-3f;
  const TransferFunction tf = table({ glm::vec4(1.0f, 1.0f, 1.0f, 0.0f),
                                      glm::vec4(0.9f, 0.8f, 0.7f, 0.95f),
                                      glm::vec4(1.0f, 1.0f, 1.0f, 0.0f) },
    v0 - w,
    v0 + w,
    2e-3f);
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(tf);
  RenderParams p = view(mesh, 24);
  p.samplesPerPass = 4;
  p.majorantResolution = glm::ivec3(32);
  const auto t0 = std::chrono::steady_clock::now();
  r.renderPass(p);
  const double ms =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<float> img = r.image();
  const RenderStats s = r.stats();
  MESSAGE("spike: ",
    ms,
    " ms, steps/sample ",
    double(s.steps) / double(s.samples),
    ", limit hits ",
    s.stepLimitHits);
  CHECK(s.majorantViolations == 0);
  CHECK(s.stepLimitHits == 0);
  CHECK(allFinite(img));
  int crossing = 0, clear = 0;
  double crossingAlpha = 0.0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
    {
      const RayQuadrature q = integrate(mesh, tf, p, x, y, 4000, v0 - w, v0 + w, 0.02f);
      const float a = img[4 * (y * 24 + x) + 3];
      if (q.crosses)
      {
        ++crossing;
        crossingAlpha += a;
      }
      if (!q.near)
      {
        ++clear;
        CHECK(a == 0.0f); // far from the spike value: nothing
      }
    }
  MESSAGE("pixels crossing the spike value: ",
    crossing,
    " (mean alpha ",
    crossingAlpha / crossing,
    "), pixels far from it: ",
    clear);
  REQUIRE(crossing > 100);
  CHECK(clear > 50);
  CHECK(crossingAlpha / crossing > 0.8);
}

TEST_CASE("density scales 1e-6 .. 1e6: finite, bounded, unbiased coverage, bounded work")
{
  const DualMesh mesh = twoLevelMesh();
  RenderParams p = view(mesh, 24);
  p.samplesPerPass = 4;
  p.maxBounces = 4;
  p.maxStepsPerWalk = 2000;
  // Per sample: at most maxBounces + 1 free flights, each followed by one shadow ray per light.
  const double walksPerSample = (p.maxBounces + 1) * (1 + p.numLights);
  // Radiance bound per sample: throughput <= 1, isotropic phase 1 / (4 pi), ambient once.
  const double bound =
    (p.maxBounces + 1) * p.lights[0].intensity / (4.0 * 3.14159265358979) + p.ambient.x;
  std::vector<double> tau(24 * 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      tau[y * 24 + x] = integrate(mesh, rampTf(1.0f), p, x, y, 2000).tau;
  CpuRenderer r;
  r.setMesh(&mesh);
  for (double scale : { 1e-6, 1e-3, 1.0, 1e3, 1e6 })
  {
    INFO("density scale ", scale);
    r.setTransferFunction(rampTf(float(1.0 / scale)));
    for (IntegratorType it : { IntegratorType::PathTracer, IntegratorType::RayMarch })
    {
      p.integrator = it;
      r.reset();
      const auto t0 = std::chrono::steady_clock::now();
      r.renderPass(p);
      const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const std::vector<float> img = r.image();
      const RenderStats s = r.stats();
      MESSAGE("scale ",
        scale,
        (it == IntegratorType::RayMarch ? " rm: " : " pt: "),
        ms,
        " ms, steps/sample ",
        double(s.steps) / double(s.samples),
        ", step-limit hits ",
        s.stepLimitHits);
      CHECK(s.majorantViolations == 0);
      CHECK(double(s.steps) <=
            double(s.samples) * walksPerSample * (p.maxStepsPerWalk + kCutFallbackSamples));
      REQUIRE(allFinite(img));
      double rmSum = 0.0, exactSum = 0.0;
      for (std::size_t i = 0; i < tau.size(); ++i)
      {
        const float* px = &img[4 * i];
        CHECK((px[3] >= 0.0f && px[3] <= 1.0f));
        CHECK((px[0] >= 0.0f && px[1] >= 0.0f && px[2] >= 0.0f));
        CHECK(std::max(px[0], std::max(px[1], px[2])) <= bound);
        rmSum += px[3];
        exactSum += -std::expm1(-scale * tau[i]);
      }
      if (it == IntegratorType::PathTracer)
        checkCoverage(r, tau, scale, 2e-3);
      else
      {
        // Ray marching is deterministic: its opacity is 1 - exp(-scale tau) up to the Riemann
        // sum (per pixel up to ~30% on grazing rays, far less over the image) at every scale.
        MESSAGE("ray marching: relative error of the mean opacity ", rmSum / exactSum - 1.0);
        CHECK(std::fabs(rmSum / exactSum - 1.0) < 0.01);
      }
      if (scale >= 1e6 && it == IntegratorType::PathTracer)
      {
        CHECK(s.stepLimitHits > 0); // the bound was hit and is reported
        // Per ray: every sample of every pixel stays within its walks' bound.
        const RenderParams rp = r.scene().resolve(p);
        const DualMeshMedium medium = r.scene().medium(rp); // what the pass ran on
        std::uint32_t worst = 0;
        for (int y = 0; y < p.height; ++y)
          for (int x = 0; x < p.width; ++x)
            for (std::uint32_t k = 0; k < 4; ++k)
            {
              TraceCounters c;
              renderSampleWith<IntegratorType::PathTracer>(
                medium, r.majorantGrid().view(), rp, x, y, k, 0, kInfinity, c);
              worst = std::max(worst, c.steps);
            }
        MESSAGE("most medium evaluations of one sample: ",
          worst,
          " (bound ",
          walksPerSample * (p.maxStepsPerWalk + kCutFallbackSamples),
          ")");
        CHECK(worst <= walksPerSample * (p.maxStepsPerWalk + kCutFallbackSamples));
      }
    }
  }
}

TEST_CASE("bounces 0 .. 1024: 0 is single scattering of the lights, 1024 terminates")
{
  const DualMesh mesh = twoLevelMesh();
  // Albedo 1 everywhere, opacity 0.6 per unit distance: a conservative scatterer.
  const auto whiteTf = [](float unitDistance)
  { return table({ glm::vec4(1.0f, 1.0f, 1.0f, 0.6f) }, 0.0f, 1.0f, unitDistance); };
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(whiteTf(0.5f));
  RenderParams p = view(mesh, 24);
  p.samplesPerPass = 4;
  auto render = [&](IntegratorType it, int bounces, glm::vec3 ambient)
  {
    RenderParams q = p;
    q.integrator = it;
    q.maxBounces = bounces;
    q.ambient = ambient;
    r.reset();
    r.renderPass(q);
    return r.image();
  };
  // 0 bounces = the single-scattering estimator without its environment term, bit for bit (the
  // path tracer never reaches the environment without a scattered ray).
  const std::vector<float> pt0 = render(IntegratorType::PathTracer, 0, glm::vec3(1.0f));
  const std::vector<float> ss = render(IntegratorType::SingleScatter, 0, glm::vec3(0.0f));
  CHECK(std::memcmp(pt0.data(), ss.data(), pt0.size() * sizeof(float)) == 0);
  // Coverage comes from the camera ray alone: identical for every bounce limit.
  const std::vector<float> pt1024 = render(IntegratorType::PathTracer, 1024, glm::vec3(1.0f));
  bool sameAlpha = true, brighter = true;
  for (std::size_t i = 0; i < pt0.size(); i += 4)
  {
    sameAlpha = sameAlpha && pt0[i + 3] == pt1024[i + 3];
    brighter = brighter && pt1024[i] >= 0.0f;
  }
  CHECK(sameAlpha);
  CHECK(brighter);
  // Without lights, 0 bounces is pure absorption: RGB exactly 0, alpha = 1 - T (quadrature).
  p.numLights = 0;
  const std::vector<float> absorb = render(IntegratorType::PathTracer, 0, glm::vec3(1.0f));
  std::vector<double> tau(24 * 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x)
      tau[y * 24 + x] = integrate(mesh, whiteTf(0.5f), p, x, y, 2000).tau;
  for (std::size_t i = 0; i < absorb.size(); i += 4)
    REQUIRE((absorb[i] == 0.0f && absorb[i + 1] == 0.0f && absorb[i + 2] == 0.0f));
  checkCoverage(r, tau, 1.0, 2e-3);

  // White furnace, 1024 bounces: albedo 1, white environment, no lights. Every path that escapes
  // brings its camera vertex's weight (sum w, transport/CameraRayEstimator.h), so the composite
  // L + (1 - alpha) = sum w + W is 1 unless the cap cut a path, up to the camera walk's Russian
  // roulette: each roulette below kCameraRouletteThreshold moves a sample by at most that much,
  // and the mean stays 1.
  for (float unitDistance : { 0.5f, 2e-4f })
  {
    r.setTransferFunction(whiteTf(unitDistance));
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<float> img = render(IntegratorType::PathTracer, 1024, glm::vec3(1.0f));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const RenderStats st = r.stats();
    REQUIRE(allFinite(img));
    double worst = 0.0, mean = 0.0;
    for (std::size_t i = 0; i < img.size(); i += 4)
    {
      const double composite = double(img[i]) + (1.0 - img[i + 3]);
      worst = std::max(worst, std::fabs(composite - 1.0));
      mean += composite / double(img.size() / 4);
      CHECK((composite >= -1e-6 && composite <= 1.0 + 8.0 * kCameraRouletteThreshold));
    }
    MESSAGE("furnace, unit distance ",
      unitDistance,
      ", 1024 bounces: ",
      s,
      " s, steps/sample ",
      double(st.steps) / double(st.samples),
      ", mean composite ",
      mean,
      ", largest |composite - 1| ",
      worst);
    CHECK(
      double(st.steps) <= double(st.samples) * 1025.0 * (p.maxStepsPerWalk + kCutFallbackSamples));
    CHECK(st.majorantViolations == 0);
    if (unitDistance > 0.1f)
    {
      // Optically thin: no path needs 1024 bounces; only the camera walk's roulette moves a
      // pixel, by a few kCameraRouletteThreshold at most, and the mean stays 1.
      CHECK(worst < 8.0 * kCameraRouletteThreshold);
      CHECK(std::fabs(mean - 1.0) < 1e-3);
    }
    else
      CHECK(mean < 0.99); // optically thick (tau ~ 10^4): the cap ends most paths
    CHECK(s < 20.0);
  }
}
