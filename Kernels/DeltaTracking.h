// The one majorant walker (pbrt-v4's SampleT_maj): exponential steps against the piecewise-
// constant majorant of DdaMajorantIterator segments, each tentative collision handed to a
// callback that decides real / null. Free flight (delta tracking) and transmittance (ratio
// tracking) are both thin callbacks over it. Unbiased for any density scale: acceptance is
// sigma_t / sigma_maj with both in world units^-1, and a zero-majorant segment is skipped.
// Host/device code.
#pragma once

#include "MajorantIterator.h"
#include "Random.h"

#include <cmath>
#include <cstdint>

namespace amrdm
{

/// What a medium reports at a world point.
struct MediumSample
{
  float sigmaT = 0.0f;       ///< extinction, world units^-1
  glm::vec3 albedo{ 0.0f };  ///< single-scattering albedo (sigma_s / sigma_t), RGB
};

/// Work counters of one sample (summed per pixel / per pass by the renderer).
struct TraceCounters
{
  std::uint32_t steps = 0;              ///< tentative collisions (medium evaluations)
  std::uint32_t primitiveTests = 0;     ///< primitive tests, when the medium counts them
  std::uint32_t stepLimitHits = 0;      ///< walks cut at maxSteps
  std::uint32_t majorantViolations = 0; ///< sigma_t > sigma_maj seen (a bug if ever > 0)
};

/// How a walk ended.
enum class WalkEnd : int
{
  Exhausted = 0, ///< reached tmax (or left the grid) without the callback stopping it
  Stopped = 1,   ///< the callback returned false
  StepLimit = 2  ///< maxSteps tentative collisions were taken
};

/// Walks `ray` over [tmin, tmax]. For every tentative collision at t (point p) calls
/// callback(t, p, mediumSample, sigmaMaj) -> bool (true = continue). Medium needs
/// `MediumSample sample(const glm::vec3& p, TraceCounters&) const`.
template <typename Medium, typename Callback>
AMRDM_HD WalkEnd sampleMajorantSegments(const Medium& medium, const MajorantGridView& grid,
  const Ray& ray, float tmin, float tmax, Rng& rng, int maxSteps, TraceCounters& counters,
  Callback&& callback)
{
  DdaMajorantIterator it(grid, ray, tmin, tmax);
  MajorantSegment seg;
  int steps = 0;
  while (it.next(seg))
  {
    if (!(seg.sigmaMaj > 0.0f))
    {
      continue; // empty macrocell: no collisions, transmittance 1
    }
    float t = seg.t0;
    for (;;)
    {
      t -= std::log(1.0f - rng.next()) / seg.sigmaMaj;
      if (!(t < seg.t1))
      {
        break; // memoryless: restart at the next segment's t0
      }
      if (steps >= maxSteps)
      {
        ++counters.stepLimitHits;
        return WalkEnd::StepLimit;
      }
      ++steps;
      ++counters.steps;
      const glm::vec3 p = ray.at(t);
      const MediumSample s = medium.sample(p, counters);
      if (s.sigmaT > seg.sigmaMaj)
      {
        ++counters.majorantViolations;
      }
      if (!callback(t, p, s, seg.sigmaMaj))
      {
        return WalkEnd::Stopped;
      }
    }
  }
  return WalkEnd::Exhausted;
}

/// Result of a free-flight sample.
struct Collision
{
  bool hit = false;          ///< a real collision happened before tmax
  bool cut = false;          ///< the walk hit the step limit (treat as absorbed)
  float t = 0.0f;
  glm::vec3 p{ 0.0f };
  MediumSample medium;
};

/// Delta tracking: the first real collision along [tmin, tmax], accepted with probability
/// sigma_t / sigma_maj. A walk cut by the step limit reports `cut` (counted).
template <typename Medium>
AMRDM_HD Collision sampleFreeFlight(const Medium& medium, const MajorantGridView& grid,
  const Ray& ray, float tmin, float tmax, Rng& rng, int maxSteps, TraceCounters& counters)
{
  Collision c;
  const WalkEnd end = sampleMajorantSegments(medium, grid, ray, tmin, tmax, rng, maxSteps, counters,
    [&](float t, const glm::vec3& p, const MediumSample& s, float sigmaMaj) {
      if (rng.next() * sigmaMaj < s.sigmaT)
      {
        c.hit = true;
        c.t = t;
        c.p = p;
        c.medium = s;
        return false;
      }
      return true;
    });
  c.cut = end == WalkEnd::StepLimit;
  return c;
}

/// Below this transmittance, ratio tracking plays Russian roulette (survival 1/2, weight x2),
/// so that thick media end the walk early without bias.
constexpr float kRatioTrackingRouletteThreshold = 0.1f;

/// Ratio tracking: unbiased transmittance estimate over [tmin, tmax], the product of
/// (1 - sigma_t / sigma_maj) over tentative collisions. A walk cut by the step limit returns 0.
template <typename Medium>
AMRDM_HD float estimateTransmittance(const Medium& medium, const MajorantGridView& grid,
  const Ray& ray, float tmin, float tmax, Rng& rng, int maxSteps, TraceCounters& counters)
{
  float T = 1.0f;
  const WalkEnd end = sampleMajorantSegments(medium, grid, ray, tmin, tmax, rng, maxSteps, counters,
    [&](float, const glm::vec3&, const MediumSample& s, float sigmaMaj) {
      T *= glm::max(0.0f, 1.0f - s.sigmaT / sigmaMaj);
      if (T < kRatioTrackingRouletteThreshold)
      {
        if (T <= 0.0f || rng.next() < 0.5f)
        {
          T = 0.0f;
          return false;
        }
        T *= 2.0f;
      }
      return true;
    });
  return end == WalkEnd::StepLimit ? 0.0f : T;
}

} // namespace amrdm
