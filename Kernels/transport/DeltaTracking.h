// The one majorant walker (pbrt-v4's SampleT_maj): exponential steps against the piecewise-
// constant majorant of DdaMajorantIterator segments, each tentative collision handed to an
// estimator that decides real / null. Free flight (delta tracking), transmittance (ratio
// tracking) and the camera ray (CameraRayEstimator.h) are estimators over the one walk(),
// which takes a WalkContext (medium, grid, stream, step limit, counters). Unbiased for any density
// scale: acceptance is sigma_t / sigma_maj with both in world units^-1, and a zero-majorant segment
// is skipped. A walk cut at the step limit (a majorant far above the density it bounds: e.g. a
// density scale of 1e6 over a macrocell that is mostly empty) finishes its remaining interval by
// regular tracking over its remaining non-empty majorant segments at the level-adaptive step
// (within a budget of kCutFallbackSamples), so its work stays bounded and its answer is close (bias
// of one stratum) instead of all-or-nothing, and a feature one finest cell wide is not skipped.
// Host/device code.
#pragma once

#include "accel/MajorantIterator.h"
#include "core/Random.h"
#include "core/WorkCounters.h"

#include <cmath>
#include <cstdint>

namespace amrdm
{

/// What a medium reports at a world point.
struct MediumSample
{
  float sigmaT = 0.0f;      ///< extinction, world units^-1
  glm::vec3 albedo{ 0.0f }; ///< single-scattering albedo (sigma_s / sigma_t), RGB
};

/// Work counters of one sample (summed per pixel / per pass by the renderer).
struct TraceCounters
{
  /// steps, primitiveTests, stepLimitHits, majorantViolations (core/WorkCounters.h).
#define AMRDM_TRACE_COUNTER(name, doc) std::uint32_t name = 0;
  AMRDM_WORK_COUNTERS(AMRDM_TRACE_COUNTER)
#undef AMRDM_TRACE_COUNTER
  /// Not a count but the one piece of sampling state a path carries: the primitive that claimed
  /// its previous sample (~0u = none). Consecutive samples of a ray mostly fall into the same
  /// gridlet or element, so DualMeshMedium tests it before descending the BVH. renderSampleWith()
  /// clears it, so a sample's result depends on its own random stream only.
  std::uint32_t lastPrimitive = ~0u;
  /// The same for the second mesh of a CompositeMedium (the coarse proxy outside a region):
  /// primitive indices of one mesh mean nothing in the other.
  std::uint32_t lastOuterPrimitive = ~0u;
  /// The primitives that claimed the previous rays' samples, by lattice slot (kRayHintSlots
  /// entries, ~0u = none; null: no table). A tile's rays are neighbours, so a ray's k-th lattice
  /// sample mostly lies in the primitive that claimed the previous ray's k-th one: DualMeshMedium
  /// tests that one next, before the BVH descent. The tile loop owns the table and clears it per
  /// tile, so a pixel's value does not depend on which thread drew the tiles before.
  std::uint32_t* rayHints = nullptr;
  /// The slot of the sample being taken (ray marching sets it around its lookup), ~0u = none.
  std::uint32_t hintSlot = ~0u;
};

/// Slots of TraceCounters::rayHints (a power of two: slot = lattice index & (slots - 1)).
constexpr std::uint32_t kRayHintSlots = 256;

/// How a walk ended.
enum class WalkEnd : int
{
  Exhausted = 0, ///< reached tmax (or left the grid) without the estimator stopping it
  Stopped = 1,   ///< the estimator's tentative() or cut() returned false
  StepLimit = 2  ///< maxSteps tentative collisions were taken
};

/// What every walk takes along a ray: the medium (`MediumSample sample(const glm::vec3& p,
/// TraceCounters&) const`), its majorant grid, the random stream, the step limit (tentative
/// collisions before the walk is cut) and the work counters. TraceContext::walker() gives a
/// sample's.
template<typename Medium>
struct WalkContext
{
  const Medium& medium;
  MajorantGridView grid;
  Rng& rng;
  int maxSteps;
  TraceCounters& counters;
};

/// A walk context (C++17 has no aggregate deduction for this shape).
template<typename Medium>
AMRDM_HD WalkContext<Medium> walkContext(const Medium& medium,
  const MajorantGridView& grid,
  Rng& rng,
  int maxSteps,
  TraceCounters& counters)
{
  return WalkContext<Medium>{ medium, grid, rng, maxSteps, counters };
}

// An estimator along a walk (FreeFlightWalk, RatioTrackingWalk, CameraRayEstimator.h's
// CameraRayWalk) is a struct with
//   bool tentative(float t, const glm::vec3& p, const MediumSample& s, float sigmaMaj)
//     a tentative collision of the majorant walker (true = continue);
//   bool beginCut()  the walk was cut at maxSteps: true = finish it by regular tracking;
//   bool cut(float t, const glm::vec3& p, const MediumSample& s, float dt)
//     one stratum of length dt of that regular tracking (true = continue).

/// Budget of medium evaluations with which a walk cut at the step limit finishes its remaining
/// interval: the work of one walk is at most maxSteps + kCutFallbackSamples evaluations (or
/// maxSteps + one per non-empty macrocell crossed, should a ray cross more than that many).
constexpr int kCutFallbackSamples = 4096;
/// Strata per finest-cell width (MajorantGridView::cellWidth) with which the cut remainder is
/// tracked while the budget allows: the level-adaptive step of the ray marcher at 2 samples per
/// cell, so a feature one finest cell wide is sampled wherever the data can hold one.
constexpr float kCutSamplesPerCell = 2.0f;

/// Strata the cut remainder wants for one non-empty majorant segment, rounded up, at least 1:
/// `weight` is the segment's wanted strata (span * kCutSamplesPerCell / cell width) and `total`
/// their sum over the remainder; with cell widths a segment takes what it wants, scaled down
/// uniformly when the remainder wants more than kCutFallbackSamples; without them both are
/// lengths and the budget is spread by length. marchCutRemainder clamps the rounded-up counts
/// so that they sum to at most kCutFallbackSamples (one each, should there be more segments).
AMRDM_HD int cutSegmentStrata(float weight, float total, bool byWidth)
{
  if (!(total > 0.0f))
  {
    return 1;
  }
  const float budget = float(kCutFallbackSamples);
  const float share = byWidth ? weight * glm::min(1.0f, budget / total) : budget * (weight / total);
  return glm::max(1, int(std::ceil(glm::min(share, budget))));
}

/// Regular tracking over [t0, t1] clipped to the grid, for a walk cut at the step limit: walks
/// the remaining majorant segments, skips the empty ones (zero majorant: no medium), and cuts
/// each non-empty one into strata of the level-adaptive step (its finest cell width /
/// kCutSamplesPerCell; by length where the grid has no cell widths), within the budget
/// kCutFallbackSamples; one sample at a shared jitter inside each stratum, in order. Calls
/// estimator.cut(t, p, mediumSample, dt) (true = continue), dt = the stratum's length.
template<typename Medium, typename Estimator>
AMRDM_HD void marchCutRemainder(const WalkContext<Medium>& w,
  const Ray& ray,
  float t0,
  float t1,
  Estimator& estimator)
{
  const MajorantGridView& grid = w.grid;
  const DdaMajorantIterator start(grid, ray, t0, t1);
  // First pass (no medium evaluations): the non-empty segments and the strata they want.
  bool byWidth = grid.cellWidth != nullptr;
  float wanted = 0.0f, length = 0.0f;
  int segments = 0;
  MajorantSegment seg;
  for (DdaMajorantIterator it = start; it.next(seg);)
  {
    if (seg.sigmaMaj > 0.0f)
    {
      ++segments;
      length += seg.t1 - seg.t0;
      const float width = byWidth ? grid.cellWidth[seg.cell] : kInfinity;
      if (width > 0.0f && width < kInfinity)
      {
        wanted += (seg.t1 - seg.t0) * kCutSamplesPerCell / width;
      }
      else
      {
        byWidth = false; // a non-empty macrocell without a width: spread the budget by length
      }
    }
  }
  const float total = byWidth ? wanted : length;
  const float jitter = w.rng.next();
  int left = kCutFallbackSamples; // budget not yet given to a segment
  for (DdaMajorantIterator it = start; it.next(seg);)
  {
    if (!(seg.sigmaMaj > 0.0f))
    {
      continue;
    }
    --segments; // non-empty segments after this one, each owed one stratum
    const float span = seg.t1 - seg.t0;
    const float weight = byWidth ? span * kCutSamplesPerCell / grid.cellWidth[seg.cell] : span;
    const int n = glm::max(1, glm::min(cutSegmentStrata(weight, total, byWidth), left - segments));
    left -= n;
    const float dt = span / float(n);
    for (int i = 0; i < n; ++i)
    {
      const float t = seg.t0 + (float(i) + jitter) * dt;
      ++w.counters.steps;
      const glm::vec3 p = ray.at(t);
      if (!estimator.cut(t, p, w.medium.sample(p, w.counters), dt))
      {
        return;
      }
    }
  }
}

/// The one walk of every estimator: walks `ray` over [tmin, tmax], calling
/// estimator.tentative(t, p, mediumSample, sigmaMaj) at every tentative collision at t (point
/// p). When it is cut at maxSteps and estimator.beginCut() returns true, it finishes the rest of
/// the interval by regular tracking calling estimator.cut() (marchCutRemainder). Returns how
/// the majorant walk ended. `majorantScale` (>= 1) walks against the majorant times that factor
/// (more, lighter tentative collisions: against a tight majorant ratio tracking is all or
/// nothing, variance T (1 - T); against k times it, exp(-tau (2 - 1/k)) - T^2); sigmaMaj is
/// then the scaled one. `firstU` (>= 0): the uniform of the first exponential step instead of
/// the stream's (e.g. a low-discrepancy value).
template<typename Medium, typename Estimator>
AMRDM_HD WalkEnd walk(const WalkContext<Medium>& w,
  const Ray& ray,
  float tmin,
  float tmax,
  Estimator& estimator,
  float majorantScale = 1.0f,
  float firstU = -1.0f)
{
  DdaMajorantIterator it(w.grid, ray, tmin, tmax);
  MajorantSegment seg;
  int steps = 0;
  float lastT = tmin;
  while (it.next(seg))
  {
    if (!(seg.sigmaMaj > 0.0f))
    {
      continue; // empty macrocell: no collisions, transmittance 1
    }
    const float sigmaMaj = seg.sigmaMaj * majorantScale;
    float t = seg.t0;
    for (;;)
    {
      // The first step may take a given uniform (firstU >= 0: the pixel's low-discrepancy
      // value), the rest the stream's.
      const float u = firstU >= 0.0f ? firstU : w.rng.next();
      firstU = -1.0f;
      t -= std::log(1.0f - u) / sigmaMaj;
      if (!(t < seg.t1))
      {
        break; // memoryless: restart at the next segment's t0
      }
      if (steps >= w.maxSteps)
      {
        ++w.counters.stepLimitHits;
        if (estimator.beginCut()) // [lastT, tmax] is unexplored
        {
          marchCutRemainder(w, ray, lastT, tmax, estimator);
        }
        return WalkEnd::StepLimit;
      }
      ++steps;
      ++w.counters.steps;
      lastT = t;
      const glm::vec3 p = ray.at(t);
      const MediumSample s = w.medium.sample(p, w.counters);
      if (s.sigmaT > seg.sigmaMaj)
      {
        ++w.counters.majorantViolations;
      }
      if (!estimator.tentative(t, p, s, sigmaMaj))
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
  bool hit = false; ///< a real collision happened before tmax
  bool cut = false; ///< the walk hit the step limit (finished by regular tracking)
  float t = 0.0f;
  glm::vec3 p{ 0.0f };
  MediumSample medium;
};

/// Delta tracking's estimator: a tentative collision is real with probability sigma_t /
/// sigma_maj; in the cut remainder the collision is where the regular-tracking optical depth
/// reaches -ln(1 - u).
struct FreeFlightWalk
{
  Rng& rng;
  Collision c;
  float target = 0.0f, depth = 0.0f;

  AMRDM_HD bool collide(float t, const glm::vec3& p, const MediumSample& s)
  {
    c.hit = true;
    c.t = t;
    c.p = p;
    c.medium = s;
    return false; // the walk ends here
  }
  AMRDM_HD bool tentative(float t, const glm::vec3& p, const MediumSample& s, float sigmaMaj)
  {
    return this->rng.next() * sigmaMaj < s.sigmaT ? this->collide(t, p, s) : true;
  }
  AMRDM_HD bool beginCut()
  {
    this->target = -std::log(1.0f - this->rng.next());
    return true;
  }
  AMRDM_HD bool cut(float t, const glm::vec3& p, const MediumSample& s, float dt)
  {
    this->depth += s.sigmaT * dt;
    return s.sigmaT > 0.0f && this->depth >= this->target ? this->collide(t, p, s) : true;
  }
};

/// Delta tracking: the first real collision along [tmin, tmax], accepted with probability
/// sigma_t / sigma_maj. A walk cut by the step limit reports `cut` (counted) and places the
/// collision on the rest of the ray where the regular-tracking optical depth reaches
/// -ln(1 - u) (no collision if it never does).
template<typename Medium>
AMRDM_HD Collision
sampleFreeFlight(const WalkContext<Medium>& w, const Ray& ray, float tmin, float tmax)
{
  FreeFlightWalk e{ w.rng };
  e.c.cut = walk(w, ray, tmin, tmax, e) == WalkEnd::StepLimit;
  return e.c;
}

/// Below this transmittance, ratio tracking plays Russian roulette (survival 1/2, weight x2),
/// so that thick media end the walk early without bias.
constexpr float kRatioTrackingRouletteThreshold = 0.1f;

/// Ratio tracking's estimator: the product of (1 - sigma_t / sigma_maj) over tentative
/// collisions (Russian roulette below kRatioTrackingRouletteThreshold); the cut remainder's
/// optical depth by regular tracking (until it blocks).
struct RatioTrackingWalk
{
  Rng& rng;
  float T = 1.0f, depth = 0.0f;

  AMRDM_HD bool tentative(float, const glm::vec3&, const MediumSample& s, float sigmaMaj)
  {
    this->T *= glm::max(0.0f, 1.0f - s.sigmaT / sigmaMaj);
    if (this->T < kRatioTrackingRouletteThreshold)
    {
      if (this->T <= 0.0f || this->rng.next() < 0.5f)
      {
        this->T = 0.0f;
        return false;
      }
      this->T *= 2.0f;
    }
    return true;
  }
  AMRDM_HD bool beginCut() { return this->T > 0.0f; }
  AMRDM_HD bool cut(float, const glm::vec3&, const MediumSample& s, float dt)
  {
    this->depth += s.sigmaT * dt;
    return this->depth < 40.0f; // exp(-40) ~ 4e-18: blocked
  }
};

/// Ratio tracking: unbiased transmittance estimate over [tmin, tmax], the product of
/// (1 - sigma_t / sigma_maj) over tentative collisions. A walk cut by the step limit multiplies
/// in exp(-optical depth) of the rest of the ray by regular tracking. `majorantScale`, `firstU`:
/// see walk().
template<typename Medium>
AMRDM_HD float estimateTransmittance(const WalkContext<Medium>& w,
  const Ray& ray,
  float tmin,
  float tmax,
  float majorantScale = 1.0f,
  float firstU = -1.0f)
{
  RatioTrackingWalk e{ w.rng };
  if (walk(w, ray, tmin, tmax, e, majorantScale, firstU) == WalkEnd::StepLimit && e.T > 0.0f)
  {
    e.T *= std::exp(-e.depth);
  }
  return e.T;
}

} // namespace amrdm
