// Rendering extremes of cameras, images and accumulation (kernel only, no VTK): rays exactly
// along dual-cell faces, edges and vertices (against cameras shifted off them), image sizes
// 1x1 .. 8192^2, and 65536 samples per pixel (against a double-precision reference). Transfer
// functions, density scales and bounces: TestRenderExtremes; the Enzo set:
// TestRenderExtremesRealData.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RenderExtremes.h"

#include <chrono>
#include <cstring>

using namespace amrdm;
using namespace amrdm_test;

namespace
{
/// Rays along -axis through every half finest cell in both image axes (64^2 pixels, parallel
/// projection, pixel centres): with a power-of-two spacing each ray lies exactly on dual-cell
/// faces (both image axes: along an edge) and passes through the vertices on its line.
/// `shiftCells` moves the camera by that many finest cells along both image axes.
RenderParams faceAlignedView(const DualMesh& mesh, int axis, float shiftCells, bool perspective)
{
  glm::vec3 lo, hi;
  worldBounds(mesh, lo, hi);
  const float h = float(mesh.finestSpacing.x);
  RenderParams p;
  p.width = p.height = perspective ? 63 : 64;
  p.pixelJitter = false;
  p.threads = 2;
  p.camera.direction = glm::vec3(0.0f);
  p.camera.direction[axis] = -1.0f;
  p.camera.up = glm::vec3(0.0f);
  p.camera.up[(axis + 2) % 3] = 1.0f;
  p.camera.parallel = !perspective;
  p.camera.parallelScale = 16.0f * h; // 64 pixels of h / 2
  p.camera.viewAngle = 50.0f;
  p.camera.position = glm::vec3(0.0f);
  p.camera.position[axis] = hi[axis] + (perspective ? 1.0f : 5.0f);
  // Perspective: the eye on the faces x = 15.5, y = 17 (grid units); parallel: pixel (0, 0) at 0.
  const glm::vec3 o0 = perspective
                         ? glm::vec3(0.0f)
                         : generateCameraRay(p.camera, p.width, p.height, 0, 0, glm::vec2(0.5f)).o;
  const glm::vec3 target = perspective ? glm::vec3(15.5f, 17.0f, 15.5f) : glm::vec3(0.0f);
  for (int a = 0; a < 3; ++a)
    if (a != axis)
      p.camera.position[a] += float(mesh.origin[a]) + h * (target[a] + shiftCells) - o0[a];
  return p;
}
} // namespace

TEST_CASE("rays exactly along dual-cell faces, edges and vertices: no pinholes")
{
  const DualMesh mesh = twoLevelMesh();
  MESSAGE("two-level mesh: ", mesh.counts.toJson());
  const TransferFunction tf = rampTf(0.5f);
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(tf);
  // Per pixel and channel, ray marching. Perspective rays leave the box through side faces, so
  // the camera shift moves their exit point and a lattice sample may drop out there (~3e-3).
  const float tolerance[2] = { 1e-3f, 2e-2f };
  for (int axis = 0; axis < 3; ++axis)
    for (bool perspective : { false, true })
    {
      INFO("axis ", axis, perspective ? " perspective" : " parallel");
      std::vector<float> images[3];
      double meanAlpha[3] = { 0.0, 0.0, 0.0 };
      // Rays exactly on the data's outer boundary see it (the domain is closed), rays shifted
      // outward do not: a true edge, not a pinhole. Compare the rays off the boundary planes.
      glm::vec3 glo, ghi;
      mesh.gridBounds(glo, ghi);
      const RenderParams p0 = faceAlignedView(mesh, axis, 0.0f, perspective);
      std::vector<char> inside(std::size_t(p0.width) * p0.height, 1);
      for (int y = 0; y < p0.height; ++y)
        for (int x = 0; x < p0.width; ++x)
        {
          const Ray ray = generateCameraRay(p0.camera, p0.width, p0.height, x, y, glm::vec2(0.5f));
          float t0 = 0.0f, t1 = kInfinity;
          worldBounds(mesh, glo, ghi);
          const float pad = 1e-3f * float(mesh.finestSpacing.x);
          for (int a = 0; a < 3; ++a)
          {
            glo[a] += a == axis ? 0.0f : pad;
            ghi[a] -= a == axis ? 0.0f : pad;
          }
          inside[std::size_t(y) * p0.width + x] = clipRayToBox(ray, glo, ghi, t0, t1);
        }
      const float shifts[3] = { 0.0f, 1e-4f, -1e-4f }; // in finest cells
      for (int k = 0; k < 3; ++k)
      {
        RenderParams p = faceAlignedView(mesh, axis, shifts[k], perspective);
        if (k == 0 && !perspective)
        {
          // The construction is exact: pixel (x, y) at grid (x / 2, y / 2) in the image axes.
          const Ray ray = generateCameraRay(p.camera, p.width, p.height, 5, 9, glm::vec2(0.5f));
          const glm::vec3 g = (ray.o - glm::vec3(mesh.origin)) / glm::vec3(mesh.finestSpacing);
          REQUIRE(g[(axis + 1) % 3] == 2.5f);
          REQUIRE(g[(axis + 2) % 3] == 4.5f);
        }
        p.integrator = IntegratorType::RayMarch;
        p.earlyTermination = 1.0f;
        r.reset();
        r.renderPass(p);
        images[k] = r.image();
        REQUIRE(allFinite(images[k]));
        // Transmittance by quadrature along the same rays (sampleField itself on the faces):
        // parallel, every third pixel; perspective, the centre row and column (in face planes).
        if (k > 0)
        {
          double worst = 0.0;
          for (int y = 0; y < p.height; y += perspective ? 1 : 3)
            for (int x = 0; x < p.width; x += perspective ? 1 : 3)
              if (inside[std::size_t(y) * p.width + x] && (!perspective || x == 31 || y == 31))
                worst = std::max(worst,
                  std::fabs(std::exp(-integrate(mesh, tf, p0, x, y, 500).tau) -
                            std::exp(-integrate(mesh, tf, p, x, y, 500).tau)));
          MESSAGE("transmittance on faces vs shifted by ",
            shifts[k],
            " cell: largest difference ",
            worst);
          CHECK(worst < 5e-4); // a dual cell missed along the ray would change it by ~0.1
        }
        p.integrator = IntegratorType::PathTracer;
        p.samplesPerPass = 8;
        r.reset();
        r.renderPass(p);
        const std::vector<float> pt = r.image();
        REQUIRE(allFinite(pt));
        for (std::size_t i = 0; i < inside.size(); ++i)
          meanAlpha[k] += inside[i] ? pt[4 * i + 3] : 0.0f;
        CHECK(r.stats().majorantViolations == 0);
      }
      for (int k = 1; k < 3; ++k)
      {
        float worst = 0.0f, boundary = 0.0f;
        for (std::size_t i = 0; i < images[0].size(); ++i)
        {
          const float d = std::fabs(images[0][i] - images[k][i]);
          (inside[i / 4] ? worst : boundary) = std::max(inside[i / 4] ? worst : boundary, d);
        }
        MESSAGE("ray marching on faces vs shifted by ",
          shifts[k],
          " cell: largest pixel difference ",
          worst,
          " (on the outer boundary ",
          boundary,
          "); path-traced alpha sum ",
          meanAlpha[0],
          " vs ",
          meanAlpha[k]);
        CHECK(worst <= tolerance[perspective]);
        CHECK(std::fabs(meanAlpha[0] - meanAlpha[k]) <= 1e-3 * meanAlpha[0]);
      }
    }
}

TEST_CASE("image sizes 1x1 .. 8192^2: every pixel, the right rays, no NaN")
{
  const DualMesh mesh = twoLevelMesh();
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(rampTf(0.5f));
  // N x N references for the degenerate shapes: 1 x N is its centre column; N x 1 its centre row
  // when the parallel scale grows by N (the image height is one pixel).
  constexpr int N = 37;
  RenderParams base = view(mesh, N);
  base.camera.parallel = true;
  base.camera.parallelScale = 2.5f;
  base.integrator = IntegratorType::RayMarch;
  base.stepSize = 0.005f;
  base.earlyTermination = 1.0f;
  base.samplesPerPass = 2;
  r.renderPass(base);
  const std::vector<float> square = r.image();
  RenderParams wide = base;
  wide.camera.parallelScale *= N;
  r.reset();
  r.renderPass(wide);
  const std::vector<float> squareWide = r.image();
  const int sizes[][2] = {
    { 1, 1 }, { 1, N }, { N, 1 }, { 17, 5 }, { 33, 31 }, { 1, 4096 }, { 4096, 1 }
  };
  for (const auto& sz : sizes)
  {
    INFO(sz[0], " x ", sz[1]);
    std::vector<float> images[2];
    for (int variant = 0; variant < 2; ++variant)
    {
      RenderParams p = sz[1] == 1 ? wide : base;
      p.width = sz[0];
      p.height = sz[1];
      p.threads = variant + 1;       // 1 thread, 16^2 tiles
      p.tileSize = variant ? 4 : 16; // 2 threads, 4^2 tiles
      r.reset();
      REQUIRE(r.renderPass(p));
      images[variant] = r.image();
      REQUIRE(images[variant].size() == std::size_t(4) * sz[0] * sz[1]);
      for (std::uint32_t c : r.sampleCounts())
        REQUIRE(c == 2u);
      CHECK(r.stats().samples == std::uint64_t(2) * sz[0] * sz[1]);
      CHECK(allFinite(images[variant]));
    }
    CHECK(std::memcmp(images[0].data(), images[1].data(), images[0].size() * sizeof(float)) == 0);
    // Ray marching with a fine step: the same ray gives the same opacity up to its jitter.
    // 1 x N: the centre column of N x N; N x 1: the centre row of the wide N x N; 1 x 1: its
    // centre.
    float worst = -1.0f;
    const bool column = sz[0] == 1 && sz[1] == N, row = sz[0] == N && sz[1] == 1;
    if (column || row || (sz[0] == 1 && sz[1] == 1))
    {
      worst = 0.0f;
      for (int i = 0; i < sz[0] * sz[1]; ++i)
      {
        const int ref = column ? i * N + N / 2 : (row ? (N / 2) * N + i : (N / 2) * N + N / 2);
        worst = std::max(
          worst, std::fabs(images[0][4 * i + 3] - (row ? squareWide : square)[4 * ref + 3]));
      }
    }
    if (worst >= 0.0f)
    {
      MESSAGE(sz[0], " x ", sz[1], ": largest opacity difference to the N x N reference ", worst);
      CHECK(worst < 0.01f);
    }
  }
  CHECK_THROWS_AS(checkAccumulationMemory(16384, 16384, std::uint64_t(1) << 30), std::length_error);
  CHECK_NOTHROW(checkAccumulationMemory(8192, 8192, std::uint64_t(1) << 40));
}

TEST_CASE("an 8192 x 8192 image: 67M pixels, 64-bit indices, bounded memory")
{
  // Cheapest setup: 1 spp, a parallel view 64 x wider than the data (most rays miss the box).
  const DualMesh mesh = twoLevelMesh();
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(rampTf(0.05f));
  RenderParams p = view(mesh, 8192);
  p.camera.parallel = true;
  p.camera.parallelScale = 64.0f * 2.0f;
  p.maxBounces = 1;
  const auto t0 = std::chrono::steady_clock::now();
  REQUIRE(r.renderPass(p));
  const double renderS =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<std::uint32_t>& counts = r.sampleCounts();
  REQUIRE(counts.size() == std::size_t(8192) * 8192);
  std::size_t wrongCount = 0;
  for (std::uint32_t c : counts)
    wrongCount += c != 1u;
  CHECK(wrongCount == 0);
  const std::vector<float> img = r.image();
  REQUIRE(img.size() == std::size_t(4) * 8192 * 8192);
  CHECK(allFinite(img));
  // The covered pixels form one blob near the centre; its area matches the data's projection.
  std::size_t covered = 0, lastCovered = 0;
  for (std::size_t i = 0; i < img.size() / 4; ++i)
    if (img[4 * i + 3] > 0.0f)
    {
      ++covered;
      lastCovered = i;
    }
  const double totalS =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MESSAGE("8192^2: render ",
    renderS,
    " s, with image() and checks ",
    totalS,
    " s; ",
    covered,
    " covered pixels; accumulation buffers ",
    (std::uint64_t(8192) * 8192 * kAccumulationBytesPerPixel) >> 20,
    " MiB");
  CHECK(covered > 1000);
  CHECK(covered < std::size_t(8192) * 8192 / 100);
  CHECK(lastCovered > std::size_t(4096) * 8192); // rows above the middle are reached (no wrap)
  CHECK(r.stats().samples == std::uint64_t(8192) * 8192);
}

TEST_CASE("65536 samples per pixel: the accumulation keeps its precision")
{
  const DualMesh mesh = twoLevelMesh();
  CpuRenderer r;
  r.setMesh(&mesh);
  RenderParams p = view(mesh, 4);
  p.camera.viewAngle = 2.0f; // all 16 rays cross the data's centre
  p.samplesPerPass = 4096;
  p.threads = 2;
  p.tileSize = 4;
  constexpr int kPasses = 16; // 65536 samples

  // A constant non-dyadic pixel: constant table, ray marching that stops at its first sample.
  r.setTransferFunction(table({ glm::vec4(0.7f, 0.3f, 0.11f, 0.9f) }, 0.0f, 1.0f, 0.01f));
  p.integrator = IntegratorType::RayMarch;
  p.earlyTermination = 0.5f;
  RenderParams one = p;
  one.samplesPerPass = 1;
  r.renderPass(one);
  const std::vector<float> single = r.image();
  r.reset();
  for (int i = 0; i < kPasses; ++i)
    r.renderPass(p);
  for (std::uint32_t c : r.sampleCounts())
    REQUIRE(c == 65536u);
  const std::vector<float> mean = r.image();
  double worst = 0.0;
  for (std::size_t i = 0; i < mean.size(); ++i)
  {
    REQUIRE(single[i] > 0.0f);
    worst = std::max(worst, std::fabs(double(mean[i]) - single[i]) / single[i]);
  }
  MESSAGE("constant pixel, 65536 samples: largest relative error of the mean ", worst);
  CHECK(worst <= 1e-6);
  for (float v : r.varianceOfMean())
    CHECK(v < 1e-12f);

  // Noisy pixels (single scattering), one sample per pass as in an interactive session: the
  // mean against a double reference over the same samples.
  r.setTransferFunction(rampTf(0.5f));
  p.integrator = IntegratorType::SingleScatter;
  p.samplesPerPass = 1;
  r.reset();
  for (int i = 0; i < 65536; ++i)
    r.renderPass(p);
  const std::vector<float> noisy = r.image();
  const RenderParams rp = r.scene().resolve(p);
  const DualMeshMedium medium = r.scene().medium(rp); // what the pass ran on
  double worstNoisy = 0.0;
  for (int px : { 0, 5, 10, 15 })
  {
    glm::dvec4 sum(0.0);
    TraceCounters c;
    for (std::uint32_t f = 0; f < 65536u; ++f)
    {
      const SampleResult s = renderSampleWith<IntegratorType::SingleScatter>(
        medium, r.majorantGrid().view(), rp, px % 4, px / 4, 0, f, kInfinity, c);
      sum += glm::dvec4(glm::vec4(s.L, s.alpha));
    }
    const glm::dvec4 ref = sum / 65536.0;
    for (int ch = 0; ch < 4; ++ch)
      worstNoisy =
        std::max(worstNoisy, std::fabs(noisy[4 * px + ch] - ref[ch]) / std::max(ref[ch], 1e-3));
  }
  MESSAGE("noisy pixels, 65536 samples: largest relative difference to the double reference ",
    worstNoisy);
  CHECK(worstNoisy <= 1e-6); // float sums: 1.1e-5
}
