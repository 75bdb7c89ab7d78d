// The camera ray of the path tracer and of single scattering, estimated along its whole length
// instead of at one collision. Most camera rays of a translucent volume pass through without a
// real collision, so delta tracking alone gives each sample all (colour, alpha 1) or nothing
// (alpha 0): at one sample per pixel that noise was larger than the picture. One walk over the
// ray's tentative collisions t_k (against kCameraMajorantScale x the majorant sigma_maj, with
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
//    (the light chosen by the low-discrepancy pair's second value).
// So a white furnace stays (nearly) noise-free and the colour follows alpha.
// A walk cut at the step limit finishes the rest of the ray by regular tracking
// (marchCutRemainder): each stratum of length dt is a tentative collision of probability
// 1 - exp(-sigma_t dt). Host/device code.
#pragma once

#include "transport/DirectLight.h"

namespace amrdm
{

/// The camera ray walks against its majorant times this factor. Against a tight majorant
/// (sigma_t = sigma_maj) ratio tracking is delta tracking, all or nothing: transmittance
/// variance T (1 - T). Against k sigma_t it is exp(-tau (2 - 1/k)) - T^2 (k = 2: 2.4x lower at
/// T = 1/2), and the path's vertex is drawn from about k candidates per unit optical depth,
/// for k times the medium evaluations of the camera ray. Chosen by measured variance x CPU time
/// (docs/BENCHMARKS-CONVERGENCE.md, 2026-12-04, 128², 16 spp): against k = 2, k = 4 cuts the
/// enzo RMSE 0.0129 -> 0.0098 (advection 0.0231 -> 0.0211) for 1.2-1.45x the CPU per pass;
/// k = 8 cuts it further (0.0075) but the statistical image test (TestPathTracerStatistics)
/// then rejects 3 of 4096 pixels, with or without ptfast's per-segment cap, not yet explained.
/// k stays 2: at k = 4 primitive culling no longer saves point-location work
/// (TestPrimitiveCulling: 45,795 tests with culling against 45,794 without), which is not yet
/// understood either; the gain (1.2x on enzo, none on advection) did not outweigh that.
constexpr float kCameraMajorantScale = 2.0f;
/// Below this transmittance the camera walk plays Russian roulette (survival 1/2, weight x2).
/// Lower than the shadow rays' kRatioTrackingRouletteThreshold: a killed walk leaves its
/// transmittance out of sum w + W = 1, so a white furnace deviates by at most this much.
constexpr float kCameraRouletteThreshold = 0.01f;
/// The largest float below 1.
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
/// The vertex choice's uniform is rescaled after each candidate; below this span of the
/// original interval (12 of its 24 bits used) it is replaced by a fresh one.
constexpr float kReservoirMinSpan = 1.0f / 4096.0f;

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

/// The camera ray's estimator along its walk (DeltaTracking.h): every tentative collision (a
/// majorant step, or a stratum of the cut remainder) with real-collision probability pc is a
/// reservoir candidate of weight W pc and multiplies the ratio-tracked transmittance W by 1 - pc.
struct CameraRayWalk
{
  Rng& rng;
  CameraRayEstimate& e;
  float u;           ///< the vertex choice's uniform, rescaled from candidate to candidate
  float span = 1.0f; ///< the fraction of the original [0, 1) u stands for
  float W = 1.0f;    ///< transmittance from the camera to the current tentative collision

  /// One tentative collision at t with real-collision probability pc; false ends the walk.
  AMRDM_HD bool visit(float t, const glm::vec3& p, const MediumSample& s, float pc)
  {
    const float w = W * pc; // the collision weight of this tentative collision
    if (w > 0.0f)
    {
      e.collisionWeight += w;
      // Reservoir step: keep t with probability q = w / sum w. Given the choice, u rescaled
      // to [0, 1) is again uniform and independent of it; once it stands for less than
      // kReservoirMinSpan of the original interval (float bits used up) a fresh uniform
      // replaces it, which has the same distribution.
      const float q = w / e.collisionWeight;
      if (u < q)
      {
        e.collision.hit = true;
        e.collision.t = t;
        e.collision.p = p;
        e.collision.medium = s;
        u = glm::min(u / q, kOneMinusEpsilon);
        span *= q;
      }
      else
      {
        u = glm::min((u - q) / (1.0f - q), kOneMinusEpsilon);
        span *= 1.0f - q;
      }
      if (span < kReservoirMinSpan)
      {
        u = rng.next();
        span = 1.0f;
      }
    }
    W *= 1.0f - pc;
    if (W > 0.0f && W < kCameraRouletteThreshold)
    {
      W = rng.next() < 0.5f ? 2.0f * W : 0.0f;
    }
    return W > 0.0f; // transmittance 0: nothing left to estimate
  }
  AMRDM_HD bool tentative(float t, const glm::vec3& p, const MediumSample& s, float sigmaMaj)
  {
    return visit(t, p, s, glm::min(1.0f, glm::max(0.0f, s.sigmaT / sigmaMaj)));
  }
  AMRDM_HD bool beginCut() { return W > 0.0f; }
  AMRDM_HD bool cut(float t, const glm::vec3& p, const MediumSample& s, float dt)
  {
    return visit(t, p, s, 1.0f - std::exp(-glm::max(0.0f, s.sigmaT) * dt));
  }
};

template<typename Medium>
AMRDM_HD CameraRayEstimate estimateCameraRay(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float tmax)
{
  CameraRayEstimate e;
  // The pixel's low-discrepancy pair: the vertex choice (one uniform for the whole reservoir,
  // kept uniform by rescaling) and the light chosen there.
  const glm::vec2 uCamera = ctx.rng.ld2(kLdCameraVertex);
  // And the first free-flight steps of the walk and of the vertex's shadow ray: in a thin medium
  // most rays have few tentative collisions, so the first one decides much of the estimate.
  const glm::vec2 uStart = ctx.rng.ld2(kLdWalkStart);
  CameraRayWalk camera{ ctx.rng, e, uCamera.x };
  e.collision.cut = walk(ctx.walker(), ray, 0.0f, tmax, camera, kCameraMajorantScale, uStart.x) ==
                    WalkEnd::StepLimit;
  e.transmittance = camera.W;
  if (e.collision.hit && maxComponent(e.collision.medium.albedo) > 0.0f)
  {
    e.singleScatter = e.collisionWeight * e.collision.medium.albedo *
                      directLight(ctx, e.collision.p, ray.d, &uCamera.y, uStart.y);
  }
  return e;
}

} // namespace amrdm
