// Scattering integrators: the volumetric path tracer (the camera ray estimated along its whole
// length, transport/CameraRayEstimator.h; then delta tracking, next-event estimation to one
// delta light per event through a ratio-tracked shadow ray, transport/DirectLight.h,
// Henyey-Greenstein phase sampling, Russian roulette, ambient environment on escape) and single
// scattering. Host/device code, templated on the medium (see Media.h).
//
// Estimator (per path): at each real collision the throughput is multiplied by the albedo
// (collision accepted with probability sigma_t / sigma_maj, so the sigma_s / sigma_t weight is
// the albedo); light arriving there is added immediately as throughput x phase x Li x Tr, so a
// path killed later by roulette keeps what it gathered (unlike the seed code, which multiplied
// by the final throughput). The lights' single scattering and the alpha of the camera ray come
// from its walk; the caller composites the background, RGB is premultiplied. Frames with lit
// isosurfaces (BlendMode Isosurface, or EmbedIsosurfaces) are path traced by
// pathTraceWithSurfaces (transport/SurfacePathTracer.h).
#pragma once

#include "transport/SurfacePathTracer.h"

namespace amrdm
{

/// The multiple-scattering path tracer over the camera ray's [0, maxT]: the camera ray by
/// estimateCameraRay (alpha, the lights' single scattering), then the path from the vertex it
/// chose, with its weight.
template<>
struct Integrate<IntegratorType::PathTracer>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx,
    const Ray& cameraRay,
    float maxT)
  {
    const RenderParams& params = ctx.params;
    if constexpr (HasIsoField<Medium>::value)
    {
      if (drawsLitSurfaces(params))
      {
        return pathTraceWithSurfaces(ctx, cameraRay, maxT); // transport/SurfacePathTracer.h
      }
    }
    SampleResult out;
    const CameraRayEstimate camera = estimateCameraRay(ctx, cameraRay, maxT);
    out.alpha = 1.0f - camera.transmittance;
    out.L = camera.singleScatter;
    Collision c = camera.collision;
    Ray ray = cameraRay;
    glm::vec3 beta(camera.collisionWeight);
    for (int bounce = 0;; ++bounce)
    {
      if (bounce > 0)
      {
        c = ctx.freeFlight(ray, kInfinity);
      }
      if (!c.hit)
      {
        if (bounce > 0)
        {
          out.L += beta * params.ambient;
        }
        break;
      }
      beta *= c.medium.albedo;
      if (!(maxComponent(beta) > 0.0f))
      {
        break; // pure absorber: no scattering work
      }
      if (bounce > 0) // the camera ray's walk counted the lights at bounce 0
      {
        out.L += beta * directLight(ctx, c.p, ray.d);
      }
      if (bounce >= params.maxBounces)
      {
        break;
      }
      if (bounce >= params.rouletteStartBounce)
      {
        // Roulette on the throughput since the camera ray's vertex: its weight (about alpha)
        // says how much of the pixel the path stands for, not how likely it is to matter.
        const float survive = glm::min(1.0f, maxComponent(beta) / camera.collisionWeight);
        if (ctx.rng.next() >= survive)
        {
          break;
        }
        beta /= survive;
      }
      float pdf;
      const glm::vec2 u = bounce == 0 ? ctx.rng.ld2(kLdFirstDirection) : ctx.rng.next2();
      const glm::vec3 d = hgSample(params.anisotropy, ray.d, u, pdf);
      // Sampling pdf equals the phase function: the weight phase / pdf is 1.
      ray.o = c.p;
      ray.d = d;
    }
    return out;
  }
};

/// Single scattering: the lights' single scattering along the camera ray (estimateCameraRay)
/// plus the ambient environment through one phase-sampled, ratio-tracked direction at the
/// vertex the camera ray's walk chose, with its weight.
template<>
struct Integrate<IntegratorType::SingleScatter>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx,
    const Ray& cameraRay,
    float maxT)
  {
    SampleResult out;
    const CameraRayEstimate camera = estimateCameraRay(ctx, cameraRay, maxT);
    out.alpha = 1.0f - camera.transmittance;
    out.L = camera.singleScatter;
    const Collision& c = camera.collision;
    const glm::vec3 beta = camera.collisionWeight * c.medium.albedo;
    if (c.hit && maxComponent(beta) > 0.0f && maxComponent(ctx.params.ambient) > 0.0f)
    {
      float pdf;
      Ray r;
      r.o = c.p;
      r.d = hgSample(ctx.params.anisotropy, cameraRay.d, ctx.rng.ld2(kLdFirstDirection), pdf);
      out.L += beta * ctx.params.ambient * ctx.transmittance(r, kInfinity);
    }
    return out;
  }
};

} // namespace amrdm
