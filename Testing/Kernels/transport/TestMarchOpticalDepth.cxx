// The automatic step's walk (transport/MarchLattice.h, marchOpticalDepth): its intervals tile
// every non-skipped macrocell segment of a ray exactly once, each holding at most tau of the
// majorant's optical depth (or minStep long), at most maxStep long, never across a skipped
// segment, one sample inside each; through rayMarch it is exact on a homogeneous medium,
// agrees with the uniform lattice on a linear ramp, takes fewer samples where the majorant is
// low, and a data-parallel region's piece (clipToBox) keeps the camera-anchored lattice.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "accel/MajorantGrid.h"
#include "transport/RayMarcher.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace amrdm;

namespace
{
struct Interval
{
  float s, e, t; // interval [s, e) and its sample
};

/// The segments the walk sees, in order.
std::vector<MajorantSegment> segments(const MajorantGridView& grid, const Ray& ray)
{
  std::vector<MajorantSegment> out;
  DdaMajorantIterator it(grid, ray, 0.0f, kInfinity);
  MajorantSegment seg;
  while (it.next(seg))
  {
    out.push_back(seg);
  }
  return out;
}

/// Majorant optical depth over [s, e).
double depth(const std::vector<MajorantSegment>& segs, float s, float e)
{
  double d = 0.0;
  for (const MajorantSegment& g : segs)
  {
    const double a = std::max(g.t0, s), b = std::min(g.t1, e);
    d += b > a ? double(g.sigmaMaj) * (b - a) : 0.0;
  }
  return d;
}
} // namespace

TEST_CASE("marchOpticalDepth: intervals tile the non-empty segments, tau each, within bounds")
{
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  MajorantGrid grid =
    makeConstantMajorantGrid(glm::vec3(0.0f), glm::vec3(1.0f), 1.0f, glm::ivec3(7));
  for (float& m : grid.majorant)
  {
    const float r = u(gen);
    m = r < 0.2f ? 0.0f : std::pow(10.0f, 3.0f * u(gen) - 1.0f); // empty, or 0.1 .. 100
  }
  const float tau = float(-std::log1p(-0.1));
  const auto empty = [](const MajorantSegment& seg) { return !(seg.sigmaMaj > 0.0f); };
  long long intervals = 0;
  for (int i = 0; i < 300; ++i)
  {
    Ray ray;
    ray.o = glm::vec3(-0.5f, u(gen), u(gen));
    ray.d = glm::normalize(glm::vec3(0.05f + 0.9f * u(gen), u(gen), u(gen)) - ray.o);
    const float minStep = 1e-3f * (1.0f + 20.0f * u(gen));
    const float maxStep = 0.02f + 0.3f * u(gen);
    const float jitter = u(gen);
    const std::vector<MajorantSegment> segs = segments(grid.view(), ray);
    std::vector<Interval> got;
    float start = 0.0f; // jitter known: the interval's start from its sample and length
    marchOpticalDepth(grid.view(),
      ray,
      kInfinity,
      minStep,
      maxStep,
      tau,
      jitter,
      empty,
      [&](float t, float length)
      {
        start = t - jitter * length;
        got.push_back({ start, start + length, t });
        return true;
      });
    intervals += long(got.size());
    // Non-empty length of the ray, and every interval inside non-empty segments only.
    double nonEmpty = 0.0, covered = 0.0;
    for (const MajorantSegment& g : segs)
    {
      nonEmpty += g.sigmaMaj > 0.0f ? double(g.t1 - g.t0) : 0.0;
    }
    for (std::size_t k = 0; k < got.size(); ++k)
    {
      const Interval& iv = got[k];
      REQUIRE(iv.e > iv.s);
      covered += double(iv.e - iv.s);
      CHECK(iv.t >= iv.s - 1e-5f);
      CHECK(iv.t <= iv.e + 1e-5f);
      CHECK(iv.e - iv.s <= std::max(maxStep, minStep) * (1.0f + 1e-5f));
      if (k > 0)
      {
        CHECK(iv.s >= got[k - 1].e - 1e-5f); // front to back, no overlap
      }
      // No skipped segment inside the interval.
      for (const MajorantSegment& g : segs)
      {
        if (!(g.sigmaMaj > 0.0f) && g.t1 > g.t0)
        {
          CHECK(!(g.t0 < iv.e - 1e-5f && g.t1 > iv.s + 1e-5f));
        }
      }
      // At most tau of majorant optical depth, unless minStep long; the last interval of a
      // non-empty run may be shorter than minStep.
      if (iv.e - iv.s > minStep * (1.0f + 1e-4f))
      {
        CHECK(depth(segs, iv.s, iv.e) <= tau * (1.0 + 1e-3) + 1e-6);
      }
    }
    CHECK(std::fabs(covered - nonEmpty) <= 1e-4 * (1.0 + nonEmpty));
  }
  MESSAGE(intervals, " intervals over 300 rays");
  CHECK(intervals > 300);
}

TEST_CASE("rayMarch at the automatic step: exact on a homogeneous medium, fewer samples where thin")
{
  HomogeneousMedium homog;
  homog.sigmaT = 2.0f;
  RenderParams p;
  p.integrator = IntegratorType::RayMarch;
  p.earlyTermination = 1.0f;
  p.stepOpticalDepth = float(-std::log1p(-0.1));
  p.stepSize = 1e-3f;
  p.maxStepSize = 0.25f;
  Ray ray;
  ray.o = glm::vec3(-0.5f, 0.3f, 0.6f);
  ray.d = glm::vec3(1.0f, 0.0f, 0.0f);
  for (float majorant : { 2.0f, 20.0f, 0.5f })
  {
    const MajorantGrid grid =
      makeConstantMajorantGrid(glm::vec3(0.0f), glm::vec3(1.0f), majorant, glm::ivec3(5));
    TraceCounters counters;
    const SampleResult r = rayMarch(homog, grid.view(), p, ray, kInfinity, 0.37f, counters);
    CHECK(std::fabs(r.alpha - (1.0f - std::exp(-2.0f))) < 2e-5f);
    // tau / majorant per interval, clamped to [stepSize, maxStepSize]: 1 / h intervals.
    const float h = std::clamp(p.stepOpticalDepth / majorant, p.stepSize, p.maxStepSize);
    MESSAGE("majorant ", majorant, ": ", counters.steps, " samples, 1 / h = ", 1.0f / h);
    CHECK(double(counters.steps) <= std::ceil(1.0 / h) + 1.0);
    CHECK(double(counters.steps) >= std::floor(1.0 / h));
  }
}

TEST_CASE(
  "rayMarch at the automatic step: a linear ramp as the uniform lattice, clipToBox keeps it")
{
  // v = x on [0, 1]^3, rgb = v (1, 0.5, 0.25), alpha = 0.6 v at unit distance 0.5 (a table of
  // 256 entries, so that each macrocell's majorant is that of its own range).
  TransferFunction tf;
  tf.table.resize(256);
  for (int i = 0; i < 256; ++i)
  {
    tf.table[i] = (float(i) / 255.0f) * glm::vec4(1.0f, 0.5f, 0.25f, 0.6f);
  }
  tf.unitDistance = 0.5f;
  LinearFieldMedium medium;
  medium.tf = tf.view();
  // The majorant of each macrocell column from its value range [x0, x1]: tfMaxExtinction.
  MajorantGrid grid =
    makeConstantMajorantGrid(glm::vec3(0.0f), glm::vec3(1.0f), 1.0f, glm::ivec3(8, 1, 1));
  for (int i = 0; i < 8; ++i)
  {
    grid.majorant[i] = tfMaxExtinction(tf.view(), i / 8.0f, (i + 1) / 8.0f);
  }
  RenderParams adaptive;
  adaptive.integrator = IntegratorType::RayMarch;
  adaptive.earlyTermination = 1.0f;
  adaptive.stepOpticalDepth = float(-std::log1p(-0.1));
  adaptive.stepSize = adaptive.stepOpticalDepth / grid.majorant[7]; // the table's densest
  adaptive.maxStepSize = 0.5f;
  RenderParams uniform = adaptive;
  uniform.stepOpticalDepth = 0.0f;
  Ray ray;
  ray.o = glm::vec3(-0.5f, 0.4f, 0.7f);
  ray.d = glm::vec3(1.0f, 0.0f, 0.0f);
  double meanA = 0.0, meanU = 0.0;
  long long stepsA = 0, stepsU = 0;
  const int n = 256;
  for (int i = 0; i < n; ++i)
  {
    const float jitter = (float(i) + 0.5f) / float(n);
    TraceCounters ca, cu;
    meanA += rayMarch(medium, grid.view(), adaptive, ray, kInfinity, jitter, ca).L.x / n;
    meanU += rayMarch(medium, grid.view(), uniform, ray, kInfinity, jitter, cu).L.x / n;
    stepsA += ca.steps;
    stepsU += cu.steps;
  }
  // The exact emission-absorption integral of this ray, by a fine midpoint sum.
  double exact = 0.0, tr = 1.0;
  const int m = 200000;
  for (int k = 0; k < m; ++k)
  {
    const double x = (k + 0.5) / m, dx = 1.0 / m;
    const double sigma = -std::log(1.0 - 0.6 * x) / 0.5;
    exact += tr * (1.0 - std::exp(-sigma * dx)) * x;
    tr *= std::exp(-sigma * dx);
  }
  MESSAGE("exact ",
    exact,
    ", adaptive ",
    meanA,
    " (",
    stepsA,
    " samples), uniform ",
    meanU,
    " (",
    stepsU,
    ")");
  CHECK(stepsA < stepsU);
  CHECK(std::fabs(meanA - exact) < 0.01);
  CHECK(std::fabs(meanU - exact) < 0.01);
  // A data-parallel region's piece samples on the lattice: the same result as the uniform step.
  RenderParams clipped = adaptive;
  clipped.clipToBox = true;
  TraceCounters c1, c2;
  const SampleResult a = rayMarch(medium, grid.view(), clipped, ray, kInfinity, 0.3f, c1);
  const SampleResult b = rayMarch(medium, grid.view(), uniform, ray, kInfinity, 0.3f, c2);
  CHECK(a.alpha == b.alpha);
  CHECK(a.L.x == b.L.x);
  CHECK(c1.steps == c2.steps);
}
