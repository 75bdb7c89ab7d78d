// Blend modes on the exact dual-mesh field (transport/BlendModes.h, Isosurface.h) on 3-level
// synthetic hierarchies with known fields: isosurface hits of a linear field (reproduced exactly
// by gridlets and elements) lie on its plane; hits of a distance field lie on the interpolant's
// surface and within the interpolation error of the analytic sphere; a value outside the field's
// range is skipped by the macrocell ranges without visiting a primitive; MIP / MinIP equal the
// brute-force extreme of dense samples along the ray to within the lattice's error; a slice
// pixel is the interpolant at the plane point; average and additive of a constant field have
// closed forms.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "ThreeLevelScene.h"

#include <cmath>
#include <random>
#include <string>

using namespace amrdm;
using amrdm_test::kHullHi;
using amrdm_test::kHullLo;
using amrdm_test::makeThreeLevelMesh;
using amrdm_test::randomDir;
using amrdm_test::randomIn;
using Scene = amrdm_test::MediumScene;

namespace
{

// Grey ramp over [lo, hi], opacity 1: a premultiplied pixel is the value's position in [lo, hi].
TransferFunction rampTf(float lo, float hi, float unitDistance = 1.0f)
{
  TransferFunction tf;
  tf.lo = lo;
  tf.hi = hi;
  tf.unitDistance = unitDistance;
  tf.table.clear();
  for (int i = 0; i < 256; ++i)
    tf.table.push_back(glm::vec4(glm::vec3(float(i) / 255.0f), 1.0f));
  return tf;
}

float sampleAt(const DualMesh& mesh, glm::vec3 p, bool* element = nullptr)
{
  float v = NAN;
  SampleHit hit;
  sampleField(mesh.view(), p, ElementTestParams(), v, &hit);
  if (element)
    *element = hit.prim != ~0u && primType(hit.prim) != PrimGridlet;
  return v;
}

} // namespace

TEST_CASE("a linear field's isosurface is its plane, hit exactly in gridlets and elements")
{
  const glm::dvec3 a(1.0 / 48.0, 0.5 / 48.0, 0.25 / 48.0);
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& p) { return float(glm::dot(a, p)); });
  Scene s(mesh, rampTf(0.0f, 1.5f));
  std::mt19937 rng(3);
  int hits = 0, elementHits = 0, expected = 0, gradients = 0;
  double worstT = 0.0, worstF = 0.0;
  for (int i = 0; i < 3000; ++i)
  {
    Ray ray;
    ray.o = randomIn(rng, kHullLo, kHullHi);
    ray.d = randomDir(rng);
    float t0 = 0.0f, tHull = kInfinity;
    clipRayToBox(ray, kHullLo, kHullHi, t0, tHull);
    // The value at a random point of the chord: a crossing the search must find (the field is
    // monotone along the ray, so it is the only one); every tenth ray a value beyond the chord.
    const bool beyond = i % 10 == 0;
    const float u = std::uniform_real_distribution<float>(0.02f, 0.98f)(rng);
    const float tTarget = beyond ? tHull + 0.5f + 5.0f * u : u * tHull;
    const float iso = float(glm::dot(a, glm::dvec3(ray.at(tTarget))));
    const double slope = glm::dot(a, glm::dvec3(ray.d));
    const double tStar = (iso - glm::dot(a, glm::dvec3(ray.o))) / slope;
    TraceCounters counters;
    const IsoHit hit = findIsoHit(s.medium, s.grid, ray, 0.0f, tHull, &iso, 1, 1.0f, counters);
    if (beyond)
    {
      CHECK_FALSE(hit.hit());
      continue;
    }
    ++expected;
    if (!hit.hit())
    {
      bool element = false;
      const float f = sampleAt(mesh, ray.at(float(tStar)), &element);
      MESSAGE("miss: o ",
        ray.o.x,
        " ",
        ray.o.y,
        " ",
        ray.o.z,
        " d ",
        ray.d.x,
        " ",
        ray.d.y,
        " ",
        ray.d.z,
        " iso ",
        iso,
        " t* ",
        tStar,
        " tHull ",
        tHull,
        " f(t*) ",
        f,
        " element ",
        element);
    }
    REQUIRE(hit.hit());
    ++hits;
    bool element = false;
    const float f = sampleAt(mesh, ray.at(hit.t), &element);
    elementHits += element;
    worstT =
      std::max(worstT, std::abs(glm::dot(a, glm::dvec3(ray.at(hit.t))) - iso) / glm::length(a));
    worstF = std::max(worstF, std::abs(double(f) - double(iso)));
    // The gradient is the field's (analytic in gridlets, a central difference at 1 % of the
    // element in elements), away from the hull's faces, beyond which the boundary layer holds
    // the field constant along the face normal.
    const glm::vec3 q = ray.at(hit.t);
    if (glm::all(glm::greaterThan(q, kHullLo + 0.2f)) && glm::all(glm::lessThan(q, kHullHi - 0.2f)))
    {
      ++gradients;
      CHECK(glm::length(glm::dvec3(hit.gradient) - a) < 1e-3 * glm::length(a));
    }
  }
  MESSAGE("linear field: ",
    hits,
    " hits of ",
    expected,
    " (",
    elementHits,
    " in stitching elements); worst distance to the plane ",
    worstT,
    " world units, worst |f(hit) - iso| ",
    worstF);
  CHECK(hits == expected);
  CHECK(gradients > 2000);
  CHECK(elementHits > 0);
  CHECK(worstT < 1e-4);
  CHECK(worstF < 1e-5);
}

TEST_CASE("a vertex-centred (point-data) mesh: the linear field's isosurface is its plane")
{
  // Primal cells over the point values (DualMesh::gridletOrigin 0), linear fields reproduced.
  const glm::dvec3 a(1.0 / 48.0, 0.5 / 48.0, 0.25 / 48.0);
  AmrHierarchy amr =
    amrdm_test::withPointData(amrdm_test::makeThreeLevelAmr([](const glm::dvec3&) { return 0.0f; }),
      [&](const glm::dvec3& v, int) { return glm::dot(a, v); });
  amr.finalizeCellStates();
  const DualMesh mesh = buildDualMesh(amr);
  REQUIRE(mesh.gridletOrigin == 0.0f);
  Scene s(mesh, rampTf(0.0f, 1.5f));
  std::mt19937 rng(11);
  double worst = 0.0;
  int hits = 0;
  const glm::vec3 lo(0.5f), hi(47.5f, 39.5f, 31.5f);
  for (int i = 0; i < 1000; ++i)
  {
    Ray ray;
    ray.o = randomIn(rng, lo, hi);
    ray.d = randomDir(rng);
    float t0 = 0.0f, t1 = kInfinity;
    clipRayToBox(ray, lo, hi, t0, t1);
    const float u = std::uniform_real_distribution<float>(0.02f, 0.98f)(rng);
    const float iso = float(glm::dot(a, glm::dvec3(ray.at(u * t1))));
    TraceCounters counters;
    const IsoHit hit = findIsoHit(s.medium, s.grid, ray, 0.0f, t1, &iso, 1, 1.0f, counters);
    REQUIRE(hit.hit());
    ++hits;
    worst =
      std::max(worst, std::abs(glm::dot(a, glm::dvec3(ray.at(hit.t))) - iso) / glm::length(a));
  }
  MESSAGE("vertex-centred linear field: ", hits, " hits, worst distance to the plane ", worst);
  CHECK(worst < 1e-4);
}

TEST_CASE("a distance field's isosurface: on the interpolant, near the analytic sphere")
{
  const glm::dvec3 c(24.0, 20.0, 16.0);
  const double R = 9.0;
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& p) { return float(glm::length(p - c)); });
  Scene s(mesh, rampTf(0.0f, 30.0f));
  const float iso = float(R);
  std::mt19937 rng(5);
  int scored = 0;
  double worstF = 0.0, worstDist = 0.0, sumDist = 0.0;
  for (int i = 0; i < 3000; ++i)
  {
    Ray ray;
    ray.o = glm::vec3(c) + float(R + 4.0) * randomDir(rng);
    const glm::vec3 target = glm::vec3(c) + std::uniform_real_distribution<float>(0.0f, 1.6f)(rng) *
                                              float(R) * randomDir(rng);
    ray.d = glm::normalize(target - ray.o);
    // Impact parameter b: the analytic sphere is hit iff b < R.
    const glm::dvec3 oc = glm::dvec3(ray.o) - c;
    const double along = -glm::dot(oc, glm::dvec3(ray.d));
    const double b = glm::length(oc + along * glm::dvec3(ray.d));
    float t0 = 0.0f, tHull = kInfinity;
    clipRayToBox(ray, kHullLo, kHullHi, t0, tHull);
    TraceCounters counters;
    const IsoHit hit = findIsoHit(s.medium, s.grid, ray, 0.0f, tHull, &iso, 1, 1.0f, counters);
    if (b > R + 1.0)
    {
      CHECK_FALSE(hit.hit());
      continue;
    }
    if (b > R - 1.0)
      continue; // grazing: the interpolant's surface may or may not be met
    REQUIRE(hit.hit());
    ++scored;
    const glm::dvec3 p(ray.at(hit.t));
    worstF = std::max(worstF, std::abs(double(sampleAt(mesh, ray.at(hit.t))) - R));
    const double dist = std::abs(glm::length(p - c) - R);
    worstDist = std::max(worstDist, dist);
    sumDist += dist;
  }
  // Trilinear interpolation error of |p - c| with cells of width h <= 4 (level 0):
  // <= h^2 / 8 * trace(Hessian) = h^2 / 8 * 2 / r, r >= R - h.
  const double bound = 16.0 / 8.0 * 2.0 / (R - 4.0);
  MESSAGE("distance field: ",
    scored,
    " hits; worst |f(hit) - iso| ",
    worstF,
    "; distance to the analytic sphere: mean ",
    sumDist / std::max(scored, 1),
    ", worst ",
    worstDist,
    " (bound ",
    bound,
    ")");
  CHECK(scored > 1000);
  CHECK(worstF < 1e-4);
  CHECK(worstDist < bound);
}

TEST_CASE("a value outside the field's range is skipped by the macrocell ranges")
{
  const DualMesh mesh = makeThreeLevelMesh([](const glm::dvec3& p) { return float(p.x / 48.0); });
  Scene s(mesh, rampTf(0.0f, 1.0f));
  Ray ray;
  ray.o = glm::vec3(-5.0f, 20.0f, 16.0f);
  ray.d = glm::normalize(glm::vec3(1.0f, 0.05f, 0.02f));
  const float outside = 5.0f, inside = 0.5f;
  TraceCounters skipped, unskipped;
  CHECK_FALSE(findIsoHit(s.medium, s.grid, ray, 0.0f, 100.0f, &outside, 1, 1.0f, skipped).hit());
  MajorantGridView noRanges = s.grid;
  noRanges.range = nullptr;
  CHECK_FALSE(
    findIsoHit(s.medium, noRanges, ray, 0.0f, 100.0f, &outside, 1, 1.0f, unskipped).hit());
  MESSAGE(
    "dual cells visited: with macrocell ranges ", skipped.steps, ", without ", unskipped.steps);
  CHECK(skipped.steps == 0);
  CHECK(unskipped.steps > 0);
  TraceCounters counters;
  const IsoHit hit = findIsoHit(s.medium, s.grid, ray, 0.0f, 100.0f, &inside, 1, 1.0f, counters);
  REQUIRE(hit.hit());
  CHECK(std::abs(ray.at(hit.t).x - 24.0f) < 1e-3f);
}

namespace
{
struct Image
{
  RenderParams params;
  std::vector<float> rgba;
};

Image render(const DualMesh& mesh,
  const TransferFunction& tf,
  BlendMode mode,
  IntegratorType integrator = IntegratorType::RayMarch)
{
  CpuRenderer renderer;
  renderer.setMesh(&mesh);
  renderer.setTransferFunction(tf);
  Image out;
  RenderParams& p = out.params;
  p.width = p.height = 24;
  p.pixelJitter = false;
  p.integrator = integrator;
  p.blendMode = mode;
  p.stepSize = 0.25f;
  p.camera.position = glm::vec3(24.0f, -50.0f, 40.0f);
  p.camera.direction = glm::vec3(0.0f, 1.0f, -0.45f);
  p.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  p.camera.viewAngle = 40.0f;
  p.sliceOrigin = glm::vec3(20.0f, 20.0f, 15.3f);
  p.sliceNormal = glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f));
  renderer.renderPass(p);
  out.rgba = renderer.image();
  return out;
}
} // namespace

TEST_CASE("MIP and MinIP equal the brute-force extreme of dense samples; slice is the interpolant")
{
  const glm::dvec3 c(24.0, 20.0, 16.0);
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& p) { return float(glm::length(p - c)); });
  const TransferFunction tf = rampTf(0.0f, 40.0f);
  const glm::vec3 boxHi(48.0f, 40.0f, 32.0f);
  for (BlendMode mode : { BlendMode::MaximumIntensity, BlendMode::MinimumIntensity })
  {
    const Image img = render(mesh, tf, mode);
    int covered = 0;
    double worst = 0.0;
    for (int y = 0; y < img.params.height; ++y)
      for (int x = 0; x < img.params.width; ++x)
      {
        const Ray ray = generateCameraRay(
          img.params.camera, img.params.width, img.params.height, x, y, glm::vec2(0.5f));
        float t0 = 0.0f, t1 = kInfinity;
        const float* px = &img.rgba[(std::size_t(y) * img.params.width + x) * 4];
        if (!clipRayToBox(ray, glm::vec3(0.0f), boxHi, t0, t1))
        {
          CHECK(px[3] == 0.0f);
          continue;
        }
        float best = mode == BlendMode::MaximumIntensity ? -1e30f : 1e30f;
        for (float t = t0; t <= t1; t += 0.01f)
        {
          const float v = sampleAt(mesh, ray.at(t));
          if (v == v)
            best = mode == BlendMode::MaximumIntensity ? std::max(best, v) : std::min(best, v);
        }
        if (std::abs(best) > 1e29f)
          continue;
        ++covered;
        // The lattice's extreme is within |grad f| * step (= 0.25, |grad f| = 1) of the true one.
        const double err = std::abs(double(px[0]) - double(best) / 40.0);
        worst = std::max(worst, err);
        CHECK(err <= 0.25 / 40.0 + 1e-5);
        CHECK(px[3] == doctest::Approx(1.0f));
      }
    MESSAGE(std::string(blendModeInfo(mode).name),
      ": ",
      covered,
      " pixels, worst |pixel - brute force| ",
      worst,
      " (bound ",
      0.25 / 40.0,
      ")");
    CHECK(covered > 200);
  }
  const Image slice = render(mesh, tf, BlendMode::Slice);
  int onPlane = 0;
  double worst = 0.0;
  for (int y = 0; y < slice.params.height; ++y)
    for (int x = 0; x < slice.params.width; ++x)
    {
      const Ray ray = generateCameraRay(
        slice.params.camera, slice.params.width, slice.params.height, x, y, glm::vec2(0.5f));
      const float t = glm::dot(slice.params.sliceOrigin - ray.o, slice.params.sliceNormal) /
                      glm::dot(ray.d, slice.params.sliceNormal);
      const float v = sampleAt(mesh, ray.at(t));
      const float* px = &slice.rgba[(std::size_t(y) * slice.params.width + x) * 4];
      if (!(v == v))
      {
        CHECK(px[3] == 0.0f);
        continue;
      }
      ++onPlane;
      worst = std::max(worst, std::abs(double(px[0]) - double(v) / 40.0));
    }
  MESSAGE("slice: ", onPlane, " pixels on the plane's data, worst |pixel - interpolant| ", worst);
  CHECK(onPlane > 80);
  CHECK(worst < 1e-5);
}

TEST_CASE("average and additive of a constant field; the path tracer says it draws Composite")
{
  const DualMesh mesh = makeThreeLevelMesh([](const glm::dvec3&) { return 0.5f; });
  const float unitDistance = 200.0f;
  const TransferFunction tf = rampTf(0.0f, 1.0f, unitDistance);
  const glm::vec3 boxHi(48.0f, 40.0f, 32.0f);
  const Image avg = render(mesh, tf, BlendMode::AverageIntensity);
  const Image add = render(mesh, tf, BlendMode::Additive);
  int covered = 0;
  for (int y = 0; y < avg.params.height; ++y)
    for (int x = 0; x < avg.params.width; ++x)
    {
      const Ray ray = generateCameraRay(
        avg.params.camera, avg.params.width, avg.params.height, x, y, glm::vec2(0.5f));
      float t0 = 0.0f, t1 = kInfinity;
      const std::size_t i = (std::size_t(y) * avg.params.width + x) * 4;
      if (!clipRayToBox(ray, glm::vec3(0.0f), boxHi, t0, t1) || t1 - t0 < 1.0f)
        continue;
      ++covered;
      CHECK(avg.rgba[i] == doctest::Approx(0.5f).epsilon(1e-5));
      CHECK(avg.rgba[i + 3] == 1.0f);
      // opacity 1 * v' 0.5 * chord / unit distance, to within one step of the lattice.
      const double expected = 0.5 * double(t1 - t0) / unitDistance;
      CHECK(std::abs(add.rgba[i] - expected) <= 0.5 * 0.25 / unitDistance + 1e-6);
    }
  CHECK(covered > 200);

  CHECK(blendModeLimitation(IntegratorType::RayMarch, BlendMode::Isosurface) == nullptr);
  // The path tracer draws isosurfaces itself, as lit surfaces (TestIsosurfacePathTracer).
  CHECK(blendModeLimitation(IntegratorType::PathTracer, BlendMode::Isosurface) == nullptr);
  CHECK(blendModeLimitation(IntegratorType::SingleScatter, BlendMode::Isosurface) != nullptr);
  CHECK(blendModeLimitation(IntegratorType::PathTracer, BlendMode::Composite) == nullptr);
  // Said once by the front-ends; the kernel then draws Composite, unchanged.
  const Image composite = render(mesh, tf, BlendMode::Composite, IntegratorType::SingleScatter);
  const Image mip = render(mesh, tf, BlendMode::MaximumIntensity, IntegratorType::SingleScatter);
  CHECK(composite.rgba == mip.rgba);
}
