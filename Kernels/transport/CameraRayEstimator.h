// The camera ray of the path tracer and of single scattering, estimated along its whole length
// instead of at one collision. Most camera rays of a translucent volume pass through without a
// real collision, so delta tracking alone gives each sample all (colour, alpha 1) or nothing
// (alpha 0): at one sample per pixel that noise was larger than the picture. One walk over the
// ray's tentative collisions t_k (against cameraMajorantScale x the majorant sigma_maj, with
// real-collision probability p_k = sigma_t / sigma_maj) gives unbiased estimates of:
//  - transmittance by ratio tracking, W_k = prod_{j<=k} (1 - p_j), so alpha = 1 - W is smooth
//    (Russian roulette below kCameraRouletteThreshold);
//  - the vertex where the path continues: one t_k drawn with probability w_k / sum w
//    (weighted reservoir sampling along the walk, one uniform from the pixel's low-discrepancy
//    sequence rescaled from candidate to candidate), with the collision weights
//    w_k = W_{k-1} p_k, and throughput sum w (= 1 - W_end without roulette): (sum w) f(t_chosen)
//    has the mean of sum_k w_k f(t_k), the integral of T sigma_t f (the ratio-tracking
//    collision estimator). Every camera ray that meets the medium scatters, weighted by about
//    its alpha, where delta tracking's 0/1 collision made most of them miss;
//  - the lights' single scattering: next-event estimation at that vertex, weighted the same
//    (the light chosen by the low-discrepancy pair's second value), or at M vertices drawn the
//    same way (RenderParams::cameraLightVertices, default 1: measured 2026-12-04, M = 4 cut the
//    variance of the light-kit sets by 12-16 % for 1.4-2.5x the pass time).
// The walk's own noise (where its tentative collisions fall) was most of the variance on the
// shared sets (docs/BENCHMARKS-CONVERGENCE.md, 2026-12-04): RenderParams::cameraMajorantScale 8
// instead of 2 cut the RMSE of enzo 1.7x at equal samples, but the statistical image test then
// rejected 3 pixels of its 4096 (min p 1.2e-8), not yet explained, so the default stays 2.
// So a white furnace stays (nearly) noise-free and the colour follows alpha.
// A walk cut at the step limit finishes the rest of the ray by regular tracking
// (marchCutRemainder): each stratum of length dt is a tentative collision of probability
// 1 - exp(-sigma_t dt). Host/device code.
#pragma once

#include "transport/DirectLight.h"

namespace amrdm
{

/// Below this transmittance the camera walk plays Russian roulette (survival 1/2, weight x2).
/// Lower than the shadow rays' kRatioTrackingRouletteThreshold: a killed walk leaves its
/// transmittance out of sum w + W = 1, so a white furnace deviates by at most this much.
constexpr float kCameraRouletteThreshold = 0.01f;
/// The largest float below 1.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
/// The vertex choice's uniform is rescaled after each candidate; below this span of the
/// original interval (12 of its 24 bits used) it is replaced by a fresh one.
constexpr float kReservoirMinSpan = 1.0f / 4096.0f;
/// A candidate whose keep probability q has q x span below this is decided by a fresh uniform:
/// the rescaled u resolves 2^-24 / span, so u < q would be off by up to 2^-8 of q.
constexpr float kReservoirMinDecision = 1.0f / 65536.0f;

/// One sample's contribution: premultiplied radiance and coverage (an unbiased estimate of
/// 1 - the camera ray's transmittance: ratio tracking for the scattering integrators).
struct SampleResult
{
  glm::vec3 L{ 0.0f };
  float alpha = 0.0f;
};

/// What the camera ray's walk gives its integrator.
struct CameraRayEstimate
{
  glm::vec3 singleScatter{ 0.0f }; ///< the lights' single scattering along the ray
  float transmittance = 1.0f;      ///< of the whole ray: alpha = 1 - transmittance
  Collision collision;             ///< where the path continues (hit = false: nowhere)
  float collisionWeight = 0.0f;    ///< the path's throughput there (sum of collision weights)
};

/// One vertex chooser over the camera walk (weighted reservoir sampling with one uniform,
/// rescaled from candidate to candidate): after the walk, `chosen` is candidate k with
/// probability w_k / sum w.
struct VertexReservoir
{
  float u = 0.0f;    ///< the uniform, rescaled to [0, 1) after each candidate
  float span = 1.0f; ///< the fraction of the original [0, 1) u stands for
  bool hit = false;
  glm::vec3 p{ 0.0f };
  glm::vec3 albedo{ 0.0f };

  /// Offers a candidate of weight w (> 0) when the weights so far sum to `total` (w included);
  /// true when it is kept. Given the choice, u rescaled to [0, 1) is again uniform and
  /// independent of it; once it stands for less than kReservoirMinSpan of the original interval
  /// (float bits used up) a fresh uniform replaces it, which has the same distribution.
  AMRDM_HD bool offer(float w, float total, const glm::vec3& at, const glm::vec3& a, Rng& rng)
  {
    const float q = w / total;
    if (q * this->span < kReservoirMinDecision)
    {
      // u resolves only 2^-24 / span: a decision this unlikely would be quantised (biased), so
      // it takes a fresh uniform of its own and leaves u (still uniform) as it is.
      const bool fresh = rng.next() < q;
      if (fresh)
      {
        this->hit = true;
        this->p = at;
        this->albedo = a;
      }
      return fresh;
    }
    const bool keep = this->u < q;
    if (keep)
    {
      this->hit = true;
      this->p = at;
      this->albedo = a;
      this->u = glm::min(this->u / q, kOneMinusEpsilon);
      this->span *= q;
    }
    else
    {
      this->u = glm::min((this->u - q) / (1.0f - q), kOneMinusEpsilon);
      this->span *= 1.0f - q;
    }
    if (this->span < kReservoirMinSpan)
    {
      this->u = rng.next();
      this->span = 1.0f;
    }
    return keep;
  }
};

/// x + y modulo 1 for x, y in [0, 1): a Cranley-Patterson rotation, uniform when x is.
AMRDM_HD float rotateUnit(float x, float y)
{
  const float r = x + y;
  return glm::min(r < 1.0f ? r : r - 1.0f, kOneMinusEpsilon);
}

/// The camera ray's walk (see the top of this file). `lightVertices` (1..
/// kMaxCameraLightVertices, clamped; default RenderParams::cameraLightVertices) is the number
/// M of next-event estimation points: M reservoirs over the same walk, reservoir j driven by
/// the pixel's uniform rotated by j / M (each marginal uniform, so each reservoir's vertex is
/// drawn with probability w_k / sum w and the mean of their M estimates is unbiased; the
/// rotation spreads them over the walk's weight instead of letting them pile up), each with its
/// own light choice (the light uniform rotated the same way) and shadow ray. The light that M
/// points see along the ray is (sum w) / M x the sum of albedo x directLight over them. The path
/// continues from reservoir 0's vertex (`collision`), exactly as with M = 1.
template<typename Medium>
AMRDM_HD CameraRayEstimate estimateCameraRay(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float tmax,
  int lightVertices = -1)
{
  CameraRayEstimate e;
  const int m = glm::clamp(
    lightVertices > 0 ? lightVertices : ctx.params.cameraLightVertices, 1, kMaxCameraLightVertices);
  float W = 1.0f; // transmittance from the camera to the current tentative collision
  // The pixel's low-discrepancy pair: the vertex choice (one uniform for the whole reservoir,
  // kept uniform by rescaling) and the light chosen there.
  const glm::vec2 uCamera = ctx.rng.ld2(kLdCameraVertex);
  // And the first free-flight steps of the walk and of the vertex's shadow ray: in a thin medium
  // most rays have few tentative collisions, so the first one decides much of the estimate.
  const glm::vec2 uStart = ctx.rng.ld2(kLdWalkStart);
  VertexReservoir reservoirs[kMaxCameraLightVertices];
  for (int j = 0; j < m; ++j)
  {
    reservoirs[j].u = rotateUnit(uCamera.x, float(j) / float(m));
  }
  // One tentative collision at t with real-collision probability pc; false ends the walk.
  auto visit = [&](float t, const glm::vec3& p, const MediumSample& s, float pc) -> bool
  {
    const float w = W * pc; // the collision weight of this tentative collision
    if (w > 0.0f)
    {
      e.collisionWeight += w;
      if (reservoirs[0].offer(w, e.collisionWeight, p, s.albedo, ctx.rng))
      {
        e.collision.hit = true;
        e.collision.t = t;
        e.collision.p = p;
        e.collision.medium = s;
      }
      for (int j = 1; j < m; ++j)
      {
        reservoirs[j].offer(w, e.collisionWeight, p, s.albedo, ctx.rng);
      }
    }
    W *= 1.0f - pc;
    if (W > 0.0f && W < kCameraRouletteThreshold)
    {
      W = ctx.rng.next() < 0.5f ? 2.0f * W : 0.0f;
    }
    return W > 0.0f; // transmittance 0: nothing left to estimate
  };
  const WalkEnd end = walk(
    ctx.medium,
    ctx.grid,
    ray,
    0.0f,
    tmax,
    ctx.rng,
    ctx.params.maxStepsPerWalk,
    ctx.counters,
    [&](float t, const glm::vec3& p, const MediumSample& s, float sigmaMaj)
    { return visit(t, p, s, glm::min(1.0f, glm::max(0.0f, s.sigmaT / sigmaMaj))); },
    [&] { return W > 0.0f; },
    [&](float t, const glm::vec3& p, const MediumSample& s, float dt)
    { return visit(t, p, s, 1.0f - std::exp(-glm::max(0.0f, s.sigmaT) * dt)); },
    glm::max(1.0f, ctx.params.cameraMajorantScale),
    uStart.x);
  e.collision.cut = end == WalkEnd::StepLimit;
  e.transmittance = W;
  glm::vec3 sum(0.0f);
  for (int j = 0; j < m; ++j)
  {
    const VertexReservoir& r = reservoirs[j];
    if (r.hit && maxComponent(r.albedo) > 0.0f)
    {
      const float shift = float(j) / float(m);
      const float uLight = rotateUnit(uCamera.y, shift);
      sum += r.albedo * directLight(ctx, r.p, ray.d, &uLight, rotateUnit(uStart.y, shift));
    }
  }
  e.singleScatter = sum * (e.collisionWeight / float(m));
  return e;
}

} // namespace amrdm
