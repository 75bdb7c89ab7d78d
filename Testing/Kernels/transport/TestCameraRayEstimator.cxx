// The path tracer's camera-ray estimator and one-light next-event estimation against analytic
// answers (kernel only): single scattering of several directional lights in a homogeneous slab
// against quadrature, for the path tracer at maxBounces 0 and for single scattering; alpha
// against 1 - exp(-sigma L) with a variance well below delta tracking's all-or-nothing one;
// a cut walk; and a path that is unchanged in mean when the lights are split into many.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "EstimatorStats.h"

#include "transport/Integrators.h"
#include "accel/MajorantGrid.h"

using namespace amrdm;
using namespace estimator_stats;

namespace
{
/// Three directional lights of different colours and strengths (a light kit's key, fill, back).
void setThreeLights(RenderParams& params)
{
  params.numLights = 3;
  const glm::vec3 dirs[3] = { { 0.3f, 1.0f, 0.2f }, { -0.6f, 0.4f, -0.5f }, { 0.1f, -0.3f, 1.0f } };
  const float intensity[3] = { 2.0f, 0.6f, 0.25f };
  const glm::vec3 color[3] = { { 1.0f, 0.9f, 0.8f }, { 0.7f, 0.8f, 1.0f }, { 1.0f, 1.0f, 1.0f } };
  for (int i = 0; i < 3; ++i)
  {
    params.lights[i].type = LightType::Directional;
    params.lights[i].direction = glm::normalize(dirs[i]);
    params.lights[i].intensity = intensity[i];
    params.lights[i].color = color[i];
  }
}

struct Slab
{
  HomogeneousMedium medium;
  MajorantGrid grid;
  Ray ray;
  Slab(float sigma, float majorantFactor)
  {
    medium.lo = glm::vec3(0.0f, -1.0f, -1.0f);
    medium.hi = glm::vec3(1.0f, 1.0f, 1.0f);
    medium.sigmaT = sigma;
    medium.albedo = glm::vec3(0.7f, 0.5f, 0.3f);
    grid = makeConstantMajorantGrid(medium.lo, medium.hi, sigma * majorantFactor, glm::ivec3(4));
    ray.o = glm::vec3(-1.0f, 0.1f, -0.2f);
    ray.d = glm::vec3(1.0f, 0.0f, 0.0f);
  }
  /// Single scattering of params' lights along the ray, channel `ch`, by quadrature.
  double exact(const RenderParams& params, int ch) const
  {
    constexpr int kQ = 20000;
    const double sigma = medium.sigmaT;
    double sum = 0.0;
    for (int l = 0; l < params.numLights; ++l)
    {
      const glm::dvec3 wi = glm::dvec3(params.lights[l].direction);
      const double phase = hgPhase(params.anisotropy, float(glm::dot(wi, glm::dvec3(ray.d))));
      const double E = params.lights[l].intensity * params.lights[l].color[ch];
      for (int i = 0; i < kQ; ++i)
      {
        const double s = (i + 0.5) / kQ;
        const glm::dvec3 p(s, 0.1, -0.2);
        const double d = exitDistance(p, wi, glm::dvec3(medium.lo), glm::dvec3(medium.hi));
        sum +=
          sigma * medium.albedo[ch] * std::exp(-sigma * s) * phase * E * std::exp(-sigma * d) / kQ;
      }
    }
    return sum;
  }
};
} // namespace

TEST_CASE("camera ray + one light per event: single scattering of three lights vs quadrature")
{
  // ld: each block of 64 samples takes the vertex choice, light choice and pixel pairs from one
  // pixel's low-discrepancy sequence (as renderSampleWith does), else the hash stream only.
  for (bool ld : { false, true })
    for (float sigma : { 0.2f, 1.5f, 6.0f })
      for (float k : { 1.0f, 3.0f })
      {
        Slab slab(sigma, k);
        RenderParams params;
        setThreeLights(params);
        params.ambient = glm::vec3(0.0f);
        params.anisotropy = 0.3f;
        params.maxBounces = 0;
        Stats single[3], path[3], alpha;
        TraceCounters counters;
        constexpr int kN = 60000;
        for (int i = 0; i < kN; ++i)
        {
          Rng rng(std::uint64_t(i), 0, 0, 5);
          Rng rng2(std::uint64_t(i), 1, 0, 5);
          if (ld)
          {
            rng.lowDiscrepancy(std::uint32_t(i % 64), hash32(std::uint32_t(i / 64)));
            rng2.lowDiscrepancy(std::uint32_t(i % 64), hash32(std::uint32_t(i / 64) + 77u));
          }
          const SampleResult s = Integrate<IntegratorType::SingleScatter>::sample(
            traceContext(slab.medium, slab.grid.view(), params, rng, counters),
            slab.ray,
            kInfinity);
          const SampleResult p = Integrate<IntegratorType::PathTracer>::sample(
            traceContext(slab.medium, slab.grid.view(), params, rng2, counters),
            slab.ray,
            kInfinity);
          for (int c = 0; c < 3; ++c)
          {
            single[c].add(s.L[c]);
            path[c].add(p.L[c]);
          }
          alpha.add(p.alpha);
        }
        INFO("sigma ", sigma, " majorant factor ", k, " low-discrepancy ", ld);
        for (int c = 0; c < 3; ++c)
        {
          const double exact = slab.exact(params, c);
          checkWithin(single[c], exact, "single scattering, channel " + std::to_string(c));
          checkWithin(path[c], exact, "path tracer maxBounces 0, channel " + std::to_string(c));
        }
        const double T = std::exp(-double(sigma));
        checkWithin(alpha, 1.0 - T, "alpha");
        // Delta tracking's alpha is 0 or 1: variance T (1 - T). Ratio tracking's is smaller.
        MESSAGE("alpha variance ", alpha.variance(), " vs delta tracking's ", T * (1.0 - T));
        CHECK(alpha.variance() < 0.75 * T * (1.0 - T)); // with the 4x camera majorant: 0.4 or less
        CHECK(counters.stepLimitHits == 0);
        CHECK(counters.majorantViolations == 0);
      }
}

TEST_CASE("one light per event: a light split into many gives the same mean")
{
  // The white furnace's cousin: one key light, and the same light split into 8 equal parts of
  // different colours that sum to white. Multiple scattering on (albedo 0.7, 64 bounces).
  Slab slab(1.2f, 2.0f);
  RenderParams one, many;
  one.numLights = 1;
  one.lights[0].direction = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  one.lights[0].intensity = 2.0f;
  one.ambient = many.ambient = glm::vec3(0.0f);
  many.numLights = kMaxLights;
  for (int i = 0; i < kMaxLights; ++i)
  {
    many.lights[i] = one.lights[0];
    many.lights[i].intensity = 2.0f / float(kMaxLights);
    many.lights[i].color = glm::vec3(i % 2 ? 1.5f : 0.5f, 1.0f, i % 2 ? 0.5f : 1.5f);
  }
  Stats a[3], b[3];
  TraceCounters counters;
  constexpr int kN = 60000;
  for (int i = 0; i < kN; ++i)
  {
    Rng r1(std::uint64_t(i), 0, 0, 9), r2(std::uint64_t(i), 1, 0, 9);
    const SampleResult x = Integrate<IntegratorType::PathTracer>::sample(
      traceContext(slab.medium, slab.grid.view(), one, r1, counters), slab.ray, kInfinity);
    const SampleResult y = Integrate<IntegratorType::PathTracer>::sample(
      traceContext(slab.medium, slab.grid.view(), many, r2, counters), slab.ray, kInfinity);
    for (int c = 0; c < 3; ++c)
    {
      a[c].add(x.L[c]);
      b[c].add(y.L[c]);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    const double diff = std::fabs(a[c].mean() - b[c].mean());
    const double se = std::hypot(a[c].stdError(), b[c].stdError());
    MESSAGE("channel ", c, ": one light ", a[c].mean(), ", eight ", b[c].mean(), " (+- ", se, ")");
    CHECK(diff <= kSigmas * se + kAbsSlack);
  }
}

TEST_CASE("a camera walk cut at the step limit still finishes its ray")
{
  // A majorant 1000x the density over a thin slab and a step limit of 16: the walk is cut and
  // regular tracking finishes it; alpha and single scattering stay close to the truth (the
  // bias of one stratum), and the path's vertex is still found.
  Slab slab(0.8f, 1000.0f);
  RenderParams params;
  setThreeLights(params);
  params.ambient = glm::vec3(0.0f);
  params.maxBounces = 0;
  params.maxStepsPerWalk = 16;
  Stats alpha, single, weight;
  TraceCounters counters;
  int collided = 0;
  constexpr int kN = 4000;
  for (int i = 0; i < kN; ++i)
  {
    Rng rng(std::uint64_t(i), 0, 0, 3);
    const CameraRayEstimate e = estimateCameraRay(
      traceContext(slab.medium, slab.grid.view(), params, rng, counters), slab.ray, kInfinity);
    alpha.add(1.0 - e.transmittance);
    single.add(e.singleScatter.x);
    collided += e.collision.hit;
    weight.add(e.collisionWeight);
    CHECK(e.collision.cut);
  }
  const double T = std::exp(-0.8);
  MESSAGE("alpha ",
    alpha.mean(),
    " vs ",
    1.0 - T,
    ", single ",
    single.mean(),
    " vs ",
    slab.exact(params, 0),
    ", collided ",
    collided,
    " of ",
    kN);
  CHECK(std::fabs(alpha.mean() - (1.0 - T)) < 0.02);
  CHECK(std::fabs(single.mean() - slab.exact(params, 0)) <
        0.05 * slab.exact(params, 0) + 4.0 * single.stdError());
  CHECK(std::fabs(weight.mean() - (1.0 - T)) < 0.02); // the continuing path's mean weight
  CHECK(collided == kN); // every walk through the slab has a vertex to continue from
  CHECK(counters.stepLimitHits >= std::uint32_t(kN)); // the camera walks, and shadow rays too
}

namespace
{
/// Extinction rising linearly along x over the unit cube, sigma(x) = a + b x: optical depth
/// along +x from x = 0 to 1 is a + b / 2.
struct RampMedium
{
  float a = 0.2f, b = 2.6f;
  AMRDM_HD MediumSample sample(const glm::vec3& p, TraceCounters&) const
  {
    MediumSample s;
    if (p.x >= 0.0f && p.x <= 1.0f && std::fabs(p.y) <= 1.0f && std::fabs(p.z) <= 1.0f)
    {
      s.sigmaT = this->a + this->b * p.x;
      s.albedo = glm::vec3(0.8f);
    }
    return s;
  }
};
} // namespace

TEST_CASE("ratio tracking against any majorant >= sigma_t is unbiased: a ramp, scales 1 to 32")
{
  // The camera walk's and the shadow rays' majorant factor trades medium evaluations for
  // variance, never the mean: a heterogeneous 1-D medium (the grid's majorant bounds it
  // loosely in the thin half, tightly at the dense end) against exp(-tau) in closed form.
  RampMedium medium;
  const MajorantGrid grid = makeConstantMajorantGrid(
    glm::vec3(0.0f, -1.0f, -1.0f), glm::vec3(1.0f), medium.a + medium.b, glm::ivec3(4));
  Ray ray;
  ray.o = glm::vec3(-1.0f, 0.1f, -0.2f);
  ray.d = glm::vec3(1.0f, 0.0f, 0.0f);
  const double T = std::exp(-(double(medium.a) + 0.5 * double(medium.b)));
  double lastVariance = 1.0;
  for (float scale : { 1.0f, 2.0f, 8.0f, 32.0f })
  {
    Stats t;
    TraceCounters counters;
    constexpr int kN = 100000;
    for (int i = 0; i < kN; ++i)
    {
      Rng rng(std::uint64_t(i), 0, 0, 11);
      t.add(estimateTransmittance(
        walkContext(medium, grid.view(), rng, 1 << 16, counters), ray, 0.0f, kInfinity, scale));
    }
    INFO("majorant scale ", scale);
    checkWithin(t, T, "ramp transmittance");
    CHECK(t.variance() < lastVariance); // more, lighter tentative collisions: less variance
    lastVariance = t.variance();
    CHECK(counters.stepLimitHits == 0);
    CHECK(counters.majorantViolations == 0);
  }
  // The camera walk (kCameraMajorantScale): alpha and the continuing path's weight.
  RenderParams params;
  params.numLights = 0;
  params.ambient = glm::vec3(0.0f);
  Stats alpha, weight, depth;
  TraceCounters counters;
  constexpr int kN = 100000;
  for (int i = 0; i < kN; ++i)
  {
    Rng rng(std::uint64_t(i), 0, 0, 13);
    const CameraRayEstimate e =
      estimateCameraRay(traceContext(medium, grid.view(), params, rng, counters), ray, kInfinity);
    alpha.add(1.0 - e.transmittance);
    weight.add(e.collisionWeight);
    // The vertex's depth into the ramp, weighted: the mean of int T sigma (x) dx over [0, 1].
    depth.add(e.collision.hit ? e.collisionWeight * (double(e.collision.p.x)) : 0.0);
  }
  checkWithin(alpha, 1.0 - T, "camera walk alpha on the ramp");
  checkWithin(weight, 1.0 - T, "camera walk vertex weight on the ramp");
  // int_0^1 x sigma(x) exp(-a x - b x^2 / 2) dx by quadrature.
  double exact = 0.0;
  constexpr int kQ = 200000;
  for (int i = 0; i < kQ; ++i)
  {
    const double x = (i + 0.5) / kQ;
    exact += x * (medium.a + medium.b * x) * std::exp(-medium.a * x - 0.5 * medium.b * x * x) / kQ;
  }
  checkWithin(depth, exact, "camera walk vertex depth on the ramp");
}
