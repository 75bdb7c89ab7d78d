// Isosurfaces in the path tracer (transport/SurfacePathTracer.h, SurfaceHits.h) and embedded in
// the volume (EmbedIsosurfaces; transport/EmbeddedIsoMarch.h for the ray marcher), on 3-level
// synthetic hierarchies whose fields have known surfaces, rendered by the CPU renderer:
//  - BlendMode Isosurface, one distant light, no environment, no bounce: a plane lit at angle
//    theta has the Lambert radiance albedo / pi x E x cos(theta) in every pixel, and the part of
//    it in the shadow of a sphere floating above it is black (the shadow ray is blocked by the
//    surface);
//  - indirect light: a convex sphere under a uniform environment A, no lights: every pixel is
//    albedo x A (cosine-sampled bounces escape; a self-hit would darken it);
//  - alpha surfaces (opacity 1/2): the mean radiance and alpha are half the opaque ones, and the
//    shadow of the (twice crossed) sphere is 1/4 of the light, within 4 standard errors;
//  - embedded: an opaque plane inside a thin homogeneous absorbing medium shows the Lambert
//    radiance x the analytic transmittance of the camera ray and of the light's ray, within a
//    statistical bound; the ray marcher composites volume then surface in depth order;
//  - off: with EmbedIsosurfaces off (or an integrator without the trait), the image is
//    byte-identical to one rendered without iso values.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "ThreeLevelScene.h"

#include <cmath>
#include <cstring>

using namespace amrdm;
using amrdm_test::insideHullXY;
using amrdm_test::kDomainHi;
using amrdm_test::kDomainLo;
using amrdm_test::makeThreeLevelMesh;

namespace
{

// One colour and opacity over [lo, hi]; entries above `blackAbove` black (absorbing only).
TransferFunction flatTf(glm::vec3 rgb,
  float opacity,
  float lo,
  float hi,
  float unitDistance = 1.0f,
  int size = 256,
  int blackAbove = 1 << 30)
{
  TransferFunction tf;
  tf.lo = lo;
  tf.hi = hi;
  tf.unitDistance = unitDistance;
  tf.table.clear();
  for (int i = 0; i < size; ++i)
    tf.table.push_back(glm::vec4(i > blackAbove ? glm::vec3(0.0f) : rgb, opacity));
  return tf;
}

const glm::vec3 kAlbedo(0.8f, 0.6f, 0.4f);
const glm::vec3 kToLight = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
constexpr float kIrradiance = 2.0f;

RenderParams baseParams(BlendMode mode, int spp)
{
  RenderParams p;
  p.width = 48;
  p.height = 40;
  p.pixelJitter = false;
  p.integrator = IntegratorType::PathTracer;
  p.blendMode = mode;
  p.samplesPerPass = spp;
  p.stepSize = 0.25f;
  p.maxBounces = 0;
  p.ambient = glm::vec3(0.0f);
  p.numLights = 1;
  p.lights[0].type = LightType::Directional;
  p.lights[0].direction = kToLight;
  p.lights[0].intensity = kIrradiance;
  p.camera.position = glm::vec3(24.0f, -14.0f, 44.0f);
  p.camera.direction = glm::vec3(24.0f, 20.0f, 8.0f) - p.camera.position;
  p.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  p.camera.viewAngle = 50.0f;
  return p;
}

std::vector<float> render(const DualMesh& mesh, const TransferFunction& tf, const RenderParams& p)
{
  CpuRenderer renderer;
  renderer.setMesh(&mesh);
  renderer.setTransferFunction(tf);
  renderer.renderPass(p);
  return renderer.image();
}

Ray pixelRay(const RenderParams& p, int px, int py)
{
  return generateCameraRay(p.camera, p.width, p.height, px, py, glm::vec2(0.5f));
}

// Ray-sphere: the nearest t >= 0, or infinity.
float hitSphere(const Ray& r, glm::vec3 c, float radius)
{
  const glm::vec3 oc = r.o - c;
  const float b = glm::dot(oc, r.d), q = glm::dot(oc, oc) - radius * radius;
  const float disc = b * b - q;
  if (disc < 0.0f)
    return kInfinity;
  const float t = -b - std::sqrt(disc);
  return t >= 0.0f ? t : kInfinity;
}

// Distance from c to the line p + s l (s >= 0).
float lineDistance(glm::vec3 p, glm::vec3 l, glm::vec3 c)
{
  const float s = glm::max(0.0f, glm::dot(c - p, l));
  return glm::length(p + s * l - c);
}

// Length of the segment p + s d, s in [0, sMax], inside the box [lo, hi].
float lengthInBox(glm::vec3 p, glm::vec3 d, float sMax, glm::vec3 lo, glm::vec3 hi)
{
  float t0 = 0.0f, t1 = sMax;
  for (int a = 0; a < 3; ++a)
  {
    const float inv = 1.0f / d[a];
    const float ta = (lo[a] - p[a]) * inv, tb = (hi[a] - p[a]) * inv;
    t0 = std::fmax(t0, std::fmin(ta, tb));
    t1 = std::fmin(t1, std::fmax(ta, tb));
  }
  return t1 > t0 ? t1 - t0 : 0.0f;
}

// Mean and standard error of a set of numbers.
struct Mean
{
  double sum = 0.0, sumSq = 0.0;
  int n = 0;
  void add(double x)
  {
    sum += x;
    sumSq += x * x;
    ++n;
  }
  double mean() const { return n ? sum / n : 0.0; }
  double stdError() const
  {
    return n > 1 ? std::sqrt(std::max(0.0, sumSq / n - mean() * mean()) / (n - 1)) : 0.0;
  }
};

// The plane-and-sphere scene: f = min(z - 4.5, |p - c|), iso 6: the plane z = 10.5 (exact where
// the field is linear in the cells around it: outside the sphere's shadow) and a sphere of
// radius 6 about c above it (the interpolant's, up to the coarsest level's 4-unit cells: the
// pixels are classified with margins).
const glm::vec3 kSphere(24.0f, 20.0f, 21.0f);
constexpr float kPlaneZ = 10.5f, kRadius = 6.0f;

float planeSphereField(const glm::dvec3& p)
{
  return float(std::min(p.z - 4.5, glm::length(p - glm::dvec3(kSphere))));
}

// Classifies each pixel of the plane-and-sphere scene: 1 = plane, lit; 2 = plane, in the
// sphere's shadow; 0 = anything else or too close to an edge. Calls visit(index, class).
template<typename Visit>
void planePixels(const RenderParams& p, Visit&& visit)
{
  for (int py = 0; py < p.height; ++py)
    for (int px = 0; px < p.width; ++px)
    {
      const Ray r = pixelRay(p, px, py);
      const float tPlane = (kPlaneZ - r.o.z) / r.d.z;
      const glm::vec3 q = r.at(tPlane);
      const bool inside = insideHullXY(glm::dvec3(q));
      if (!(tPlane > 0.0f) || !inside || hitSphere(r, kSphere, kRadius + 1.5f) < tPlane)
        continue;
      const float d = lineDistance(q, kToLight, kSphere);
      const int cls = d > kRadius + 1.5f ? 1 : d < kRadius - 2.0f ? 2 : 0;
      if (cls)
        visit(py * p.width + px, cls);
    }
}

} // namespace

TEST_CASE("path-traced isosurface: Lambert radiance on the lit plane, black in the shadow")
{
  const DualMesh mesh = makeThreeLevelMesh(planeSphereField);
  const TransferFunction tf = flatTf(kAlbedo, 1.0f, 0.0f, 40.0f);
  RenderParams p = baseParams(BlendMode::Isosurface, 4);
  p.numIsoValues = 1;
  p.isoValues[0] = kRadius;
  CHECK(blendModeLimitation(IntegratorType::PathTracer, BlendMode::Isosurface) == nullptr);
  const std::vector<float> img = render(mesh, tf, p);
  const glm::vec3 lambert = kAlbedo / float(M_PI) * kIrradiance * kToLight.z;
  int lit = 0, shadowed = 0;
  double worstLit = 0.0, worstShadow = 0.0;
  planePixels(p,
    [&](int i, int cls)
    {
      const glm::vec3 L(img[4 * i], img[4 * i + 1], img[4 * i + 2]);
      CHECK(img[4 * i + 3] == doctest::Approx(1.0f));
      if (cls == 1)
      {
        ++lit;
        worstLit = std::max(worstLit, double(glm::length(L - lambert) / glm::length(lambert)));
      }
      else
      {
        ++shadowed;
        worstShadow = std::max(worstShadow, double(glm::length(L)));
      }
    });
  MESSAGE("lit plane pixels ",
    lit,
    " (worst relative error ",
    worstLit,
    "), shadowed ",
    shadowed,
    " (brightest ",
    worstShadow,
    ")");
  CHECK(lit > 200);
  CHECK(shadowed > 10);
  // One light, opacity 1, no bounce: the estimate is deterministic (float rounding, and the
  // interpolant's plane bent by the sphere's distance field in a few coarse cells).
  CHECK(worstLit < 1e-2);
  CHECK(worstShadow < 1e-6);
}

TEST_CASE("path-traced isosurface with Shade: the optional Blinn-Phong lobe on the lit plane")
{
  const DualMesh mesh = makeThreeLevelMesh(planeSphereField);
  const TransferFunction tf = flatTf(kAlbedo, 1.0f, 0.0f, 40.0f);
  RenderParams p = baseParams(BlendMode::Isosurface, 1);
  p.numIsoValues = 1;
  p.isoValues[0] = kRadius;
  p.gradientShading = true; // vtkVolumeProperty Shade: Specular and SpecularPower apply
  p.specularCoefficient = 0.5f;
  p.specularPower = 20.0f;
  const std::vector<float> img = render(mesh, tf, p);
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  double worst = 0.0, brightest = 0.0, sum = 0.0;
  int lit = 0;
  planePixels(p,
    [&](int i, int cls)
    {
      if (cls != 1)
        return;
      const Ray r = pixelRay(p, i % p.width, i / p.width);
      const glm::vec3 h = glm::normalize(kToLight - r.d);
      const float spec = 0.5f * 22.0f * 0.5f * std::pow(glm::dot(n, h), 20.0f);
      const glm::vec3 expected =
        (0.5f * kAlbedo + glm::vec3(spec)) * (kIrradiance * kToLight.z / float(M_PI));
      const glm::vec3 L(img[4 * i], img[4 * i + 1], img[4 * i + 2]);
      const double err = glm::length(L - expected) / glm::length(expected);
      worst = std::max(worst, err);
      sum += err;
      brightest = std::max(brightest, double(spec));
      ++lit;
    });
  MESSAGE("lit plane pixels ",
    lit,
    ": mean relative error ",
    sum / lit,
    ", worst ",
    worst,
    ", largest lobe ",
    brightest);
  CHECK(lit > 200);
  CHECK(brightest > 0.5); // the highlight is in the picture
  // Deterministic (one light, no bounce); the power 20 lobe magnifies the interpolant's normal
  // error where the sphere's distance field bends the plane in a few coarse cells.
  CHECK(sum / lit < 1e-3);
  CHECK(worst < 3e-2);
}

TEST_CASE("path-traced isosurface: a convex sphere under a uniform environment is albedo x A")
{
  const glm::vec3 c(24.0f, 20.0f, 16.0f);
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& q) { return float(glm::length(q - glm::dvec3(c))); });
  const TransferFunction tf = flatTf(kAlbedo, 1.0f, 0.0f, 40.0f);
  RenderParams p = baseParams(BlendMode::Isosurface, 8);
  p.numIsoValues = 1;
  p.isoValues[0] = 8.0f;
  p.numLights = 0;
  p.ambient = glm::vec3(0.5f);
  p.maxBounces = 4;
  const std::vector<float> img = render(mesh, tf, p);
  Mean ratio;
  double worst = 0.0;
  for (int py = 0; py < p.height; ++py)
    for (int px = 0; px < p.width; ++px)
    {
      const Ray r = pixelRay(p, px, py);
      if (hitSphere(r, c, 7.5f) == kInfinity)
        continue;
      const int i = py * p.width + px;
      const double v = img[4 * i] / (kAlbedo.x * 0.5);
      ratio.add(v);
      worst = std::max(worst, std::fabs(v - 1.0));
    }
  MESSAGE(
    "sphere pixels ", ratio.n, ": mean radiance / (albedo A) ", ratio.mean(), ", worst ", worst);
  CHECK(ratio.n > 100);
  CHECK(std::fabs(ratio.mean() - 1.0) < 0.01);
  CHECK(worst < 0.1);
}

TEST_CASE("alpha isosurfaces: opacity 1/2 halves radiance and alpha, the sphere's shadow is 1/4")
{
  const DualMesh mesh = makeThreeLevelMesh(planeSphereField);
  const TransferFunction tf = flatTf(kAlbedo, 0.5f, 0.0f, 40.0f);
  RenderParams p = baseParams(BlendMode::Isosurface, 64);
  p.numIsoValues = 1;
  p.isoValues[0] = kRadius;
  const std::vector<float> img = render(mesh, tf, p);
  const double lambert = kAlbedo.x / M_PI * kIrradiance * kToLight.z;
  Mean lit, shadow, alpha;
  planePixels(p,
    [&](int i, int cls)
    {
      (cls == 1 ? lit : shadow).add(img[4 * i] / lambert);
      alpha.add(img[4 * i + 3]);
    });
  // A pixel's 64 samples each stop at the plane with probability 1/2: its mean has standard
  // deviation 1/16 of the stopped value; the shadow ray crosses the sphere twice (1/4).
  const double seLit = 0.5 / std::sqrt(64.0 * lit.n), seShadow = 0.125 / std::sqrt(64.0 * shadow.n);
  const double seAlpha = 0.5 / std::sqrt(64.0 * alpha.n);
  MESSAGE("lit ",
    lit.mean(),
    " (expect 0.5 +- ",
    seLit,
    "), shadow ",
    shadow.mean(),
    " (expect 0.125 +- ",
    seShadow,
    "), alpha ",
    alpha.mean());
  REQUIRE(lit.n > 200);
  REQUIRE(shadow.n > 10);
  CHECK(std::fabs(lit.mean() - 0.5) < 4.0 * seLit);
  CHECK(std::fabs(shadow.mean() - 0.125) < 4.0 * seShadow);
  CHECK(std::fabs(alpha.mean() - 0.5) < 4.0 * seAlpha);
}

namespace
{
// The embedded scene: f = z, iso 10.495 (the plane z = 10.495) inside a homogeneous medium of
// table opacity 1 (extinction -ln(1 - kMaxTableOpacity) / unitDistance), black above the plane
// (absorbing only: nothing scatters toward the camera), white at and below it.
constexpr float kIso = 10.495f, kUnit = 300.0f;
TransferFunction embeddedTf()
{
  // 4096 entries over [0, 40.95]: entry i at value i / 100; the surface's value between 1049
  // and 1050, both white.
  return flatTf(glm::vec3(0.9f), 1.0f, 0.0f, 40.95f, kUnit, 4096, 1050);
}

/// The embedded scene rendered by `integrator` at `spp` samples per pixel; `params` gets the
/// parameters it was rendered with.
std::vector<float> renderEmbedded(IntegratorType integrator, int spp, RenderParams& params)
{
  const DualMesh mesh = makeThreeLevelMesh([](const glm::dvec3& q) { return float(q.z); });
  params = baseParams(BlendMode::Composite, spp);
  params.integrator = integrator;
  params.embedIsosurfaces = true;
  params.numIsoValues = 1;
  params.isoValues[0] = kIso;
  return render(mesh, embeddedTf(), params);
}

/// visit(pixel index, ray, t and point where the ray meets the plane z = kIso) for each pixel
/// whose plane point lies inside the hull by more than one cell (insideHullXY).
template<typename Visit>
void forPlanePixels(const RenderParams& p, Visit visit)
{
  for (int py = 0; py < p.height; ++py)
    for (int px = 0; px < p.width; ++px)
    {
      const Ray r = pixelRay(p, px, py);
      const float tPlane = (kIso - r.o.z) / r.d.z;
      const glm::vec3 q = r.at(tPlane);
      if (insideHullXY(glm::dvec3(q)))
        visit(py * p.width + px, r, tPlane, q);
    }
}
} // namespace

TEST_CASE("embedded isosurface: Lambert x the medium's transmittance to the camera and light")
{
  RenderParams p;
  const std::vector<float> img = renderEmbedded(IntegratorType::PathTracer, 16, p);
  const float sigma = -std::log(1.0f - kMaxTableOpacity) / kUnit;
  const double lambert = 0.9 / M_PI * kIrradiance * kToLight.z;
  Mean ratio, plain;
  forPlanePixels(p,
    [&](int i, const Ray& r, float tPlane, const glm::vec3& q)
    {
      const float camera = lengthInBox(r.o, r.d, tPlane, kDomainLo, kDomainHi);
      const float light = lengthInBox(q, kToLight, 1e3f, kDomainLo, kDomainHi);
      const double expected = lambert * std::exp(-sigma * (camera + light));
      ratio.add(img[4 * i] / expected);
      plain.add(img[4 * i] / lambert);
      CHECK(img[4 * i + 3] == doctest::Approx(1.0f));
    });
  MESSAGE("plane pixels ",
    ratio.n,
    ": measured / (Lambert x T_camera x T_light) ",
    ratio.mean(),
    " +- ",
    ratio.stdError(),
    "; measured / Lambert ",
    plain.mean());
  REQUIRE(ratio.n > 500);
  // Ratio- and delta-tracking are unbiased; the grey layer between the table's black and white
  // entries (0.01 units of white medium above the plane) adds < 0.2 %.
  CHECK(std::fabs(ratio.mean() - 1.0) < 4.0 * ratio.stdError() + 0.003);
  CHECK(plain.mean() < 0.8); // the medium attenuates: the test would see a missing volume
}

TEST_CASE("embedded isosurface, ray marcher: volume then surface in depth order")
{
  RenderParams p;
  const std::vector<float> img = renderEmbedded(IntegratorType::RayMarch, 1, p);
  const float sigma = -std::log(1.0f - kMaxTableOpacity) / kUnit;
  double worst = 0.0;
  int n = 0;
  forPlanePixels(p,
    [&](int i, const Ray& r, float tPlane, const glm::vec3&)
    {
      // Black volume in front (alpha 1 - T), then the white surface behind it: C = T x 0.9.
      const float T = std::exp(-sigma * lengthInBox(r.o, r.d, tPlane, kDomainLo, kDomainHi));
      worst = std::max(worst, double(std::fabs(img[4 * i] - 0.9f * T)));
      CHECK(img[4 * i + 3] == doctest::Approx(1.0f));
      ++n;
    });
  MESSAGE("ray-marched plane pixels ", n, ", worst |C - 0.9 T| ", worst);
  REQUIRE(n > 500);
  CHECK(worst < 0.01); // the lattice's quantisation of the piece's length (step 0.25)
}

TEST_CASE("EmbedIsosurfaces off, or an integrator without the trait: the image of no iso values")
{
  const DualMesh mesh = makeThreeLevelMesh(planeSphereField);
  const TransferFunction tf = flatTf(kAlbedo, 0.3f, 0.0f, 40.0f, 20.0f);
  for (IntegratorType integrator :
    { IntegratorType::PathTracer, IntegratorType::RayMarch, IntegratorType::SingleScatter })
  {
    RenderParams p = baseParams(BlendMode::Composite, 2);
    p.integrator = integrator;
    p.maxBounces = 8;
    p.ambient = glm::vec3(0.3f);
    const std::vector<float> none = render(mesh, tf, p);
    p.numIsoValues = 1;
    p.isoValues[0] = kRadius;
    const std::vector<float> off = render(mesh, tf, p);
    CHECK(std::memcmp(none.data(), off.data(), none.size() * sizeof(float)) == 0);
    p.embedIsosurfaces = true;
    const std::vector<float> on = render(mesh, tf, p);
    const bool drawn = integratorInfo(integrator).embedsIsosurfaces;
    CHECK((embedIsosurfacesLimitation(integrator, true) == nullptr) == drawn);
    // With the trait the surfaces change the image; without it the flag is ignored.
    CHECK((std::memcmp(none.data(), on.data(), none.size() * sizeof(float)) != 0) == drawn);
  }
}
