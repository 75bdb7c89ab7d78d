// Scattering integrators: the volumetric path tracer (delta tracking, next-event estimation to
// delta lights through ratio-tracked shadow rays, Henyey-Greenstein phase sampling, Russian
// roulette, ambient environment on escape) and single scattering. Host/device code, templated
// on the medium (see Media.h).
//
// Estimator (per path): at each real collision the throughput is multiplied by the albedo
// (collision accepted with probability sigma_t / sigma_maj, so the sigma_s / sigma_t weight is
// the albedo); light arriving there is added immediately as throughput x phase x Li x Tr, so a
// path killed later by roulette keeps what it gathered (unlike the seed code, which multiplied
// by the final throughput). Camera rays that escape contribute no colour and alpha 0: the
// caller composites the background, RGB is premultiplied.
#pragma once

#include "transport/PhaseFunction.h"
#include "transport/TraceContext.h"

namespace amrdm
{

/// One sample's contribution: premultiplied radiance and coverage (1 if the camera ray had a
/// real collision, else 0; its mean is 1 - transmittance of the primary ray).
struct SampleResult
{
  glm::vec3 L{ 0.0f };
  float alpha = 0.0f;
};

AMRDM_HD float maxComponent(const glm::vec3& v)
{
  return glm::max(v.x, glm::max(v.y, v.z));
}

/// Sum over lights of phase x Li x transmittance at p for a path travelling along `dIn`.
template<typename Medium>
AMRDM_HD glm::vec3 directLight(const TraceContext<Medium>& ctx,
  const glm::vec3& p,
  const glm::vec3& dIn)
{
  const RenderParams& params = ctx.params;
  glm::vec3 L(0.0f);
  for (int i = 0; i < params.numLights && i < kMaxLights; ++i)
  {
    const LightSample ls = sampleLight(params.lights[i], p);
    // Light travels along -wi, then scatters into -dIn: cos(theta) = dot(wi, dIn).
    const glm::vec3 f = ls.Li * hgPhase(params.anisotropy, glm::dot(ls.wi, dIn));
    if (!(maxComponent(f) > 0.0f))
    {
      continue;
    }
    Ray shadow;
    shadow.o = p;
    shadow.d = ls.wi;
    L += f * ctx.transmittance(shadow, ls.distance);
  }
  return L;
}

/// The multiple-scattering path tracer over the camera ray's [0, maxT].
template<>
struct Integrate<IntegratorType::PathTracer>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx,
    const Ray& cameraRay,
    float maxT)
  {
    const RenderParams& params = ctx.params;
    SampleResult out;
    Ray ray = cameraRay;
    float rayMax = maxT;
    glm::vec3 beta(1.0f);
    for (int bounce = 0;; ++bounce)
    {
      const Collision c = ctx.freeFlight(ray, rayMax);
      if (!c.hit)
      {
        if (bounce > 0)
        {
          out.L += beta * params.ambient;
        }
        break;
      }
      if (bounce == 0)
      {
        out.alpha = 1.0f;
      }
      beta *= c.medium.albedo;
      if (!(maxComponent(beta) > 0.0f))
      {
        break; // pure absorber: no scattering work
      }
      out.L += beta * directLight(ctx, c.p, ray.d);
      if (bounce >= params.maxBounces)
      {
        break;
      }
      if (bounce >= params.rouletteStartBounce)
      {
        const float survive = glm::min(1.0f, maxComponent(beta));
        if (ctx.rng.next() >= survive)
        {
          break;
        }
        beta /= survive;
      }
      float pdf;
      const glm::vec3 d = hgSample(params.anisotropy, ray.d, ctx.rng.next2(), pdf);
      // Sampling pdf equals the phase function: the weight phase / pdf is 1.
      ray.o = c.p;
      ray.d = d;
      rayMax = kInfinity;
    }
    return out;
  }
};

/// Single scattering: the first real collision, lit by the lights (NEE) and by the ambient
/// environment through one phase-sampled, ratio-tracked direction.
template<>
struct Integrate<IntegratorType::SingleScatter>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx,
    const Ray& cameraRay,
    float maxT)
  {
    SampleResult out;
    const Collision c = ctx.freeFlight(cameraRay, maxT);
    if (!c.hit)
    {
      return out;
    }
    out.alpha = 1.0f;
    const glm::vec3 beta = c.medium.albedo;
    if (!(maxComponent(beta) > 0.0f))
    {
      return out;
    }
    out.L += beta * directLight(ctx, c.p, cameraRay.d);
    if (maxComponent(ctx.params.ambient) > 0.0f)
    {
      float pdf;
      Ray r;
      r.o = c.p;
      r.d = hgSample(ctx.params.anisotropy, cameraRay.d, ctx.rng.next2(), pdf);
      out.L += beta * ctx.params.ambient * ctx.transmittance(r, kInfinity);
    }
    return out;
  }
};

} // namespace amrdm
