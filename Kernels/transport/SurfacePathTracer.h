// The path tracer with isosurfaces as surfaces (transport/SurfaceHits.h), for BlendMode
// Isosurface (the surfaces alone: no volume) and for EmbedIsosurfaces (the surfaces inside the
// Composite volume). Integrate<PathTracer> (transport/PathTracer.h) hands such frames here.
//
// A surface is a Lambertian reflector, BRDF albedo / pi, albedo = the transfer function's colour
// at its value (VTK colours isosurfaces so), opacity = the transfer function's opacity there
// (an alpha surface below 1: SurfaceHits.h). No specular term (not built; see docs/ISOSURFACES.md).
//
// Estimator (per sample):
//  - the camera ray stops at the first surface it is accepted by (traceSurface), at t_s (maxT
//    if none); with a volume, its part [0, t_s] is estimated by the volume path tracer's
//    camera walk (estimateCameraRay: transmittance W, the lights' single scattering, a vertex in
//    the medium with weight sum w), so the volume in front of a surface attenuates it by W;
//  - the surface: next-event estimation x W: albedo / pi x Li x cos x the shadow ray's
//    transmittance (shadowTransmittance: the surfaces' prod (1 - opacity) times the volume's
//    ratio tracking: a surface shadows the volume and the volume shadows the surface);
//  - the path continues from ONE of the two vertices (the medium's, the surface's), chosen
//    with probability proportional to its weight (sum w x albedo, W x albedo), divided by that
//    probability; at a surface a cosine-weighted direction (weight = albedo), in the medium the
//    phase function; each next segment ends at the next surface it is accepted by or at the
//    next real collision before it (delta tracking over [0, t_s]), with NEE at either; an
//    escaping path sees the ambient environment. Russian roulette as the volume path tracer.
//  - alpha: 1 where the camera ray stops at a surface, else 1 - W.
// Host/device code.
#pragma once

#include "transport/CameraRayEstimator.h"

#include <cmath>

namespace amrdm
{

constexpr float kInvPi = 0.3183098861837907f; ///< 1 / pi

/// A cosine-weighted direction about the unit normal n (pdf cos / pi): with a Lambertian BRDF
/// the path's weight is the albedo.
AMRDM_HD glm::vec3 cosineSampleHemisphere(const glm::vec3& n, const glm::vec2& u)
{
  const float r = std::sqrt(u.x), phi = kTwoPi * u.y;
  const float x = r * std::cos(phi), y = r * std::sin(phi);
  const float z = std::sqrt(glm::max(0.0f, 1.0f - u.x));
  // Orthonormal basis about n (Duff et al. 2017).
  const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sign + n.z), b = n.x * n.y * a;
  const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const glm::vec3 s(b, sign + n.y * n.y * a, -n.y);
  return glm::normalize(x * t + y * s + z * n);
}

/// Next-event estimation at a surface: sum over lights of Li x cos / pi x the shadow ray's
/// transmittance (one shadow ray, directLightWith); times the albedo it is the reflected
/// radiance. Lights behind the surface (cos <= 0) reflect nothing.
template<typename Medium>
AMRDM_HD glm::vec3 surfaceDirectLight(const TraceContext<Medium>& ctx, const SurfaceHit& s)
{
  const glm::vec3 n = s.n;
  return directLightWith(ctx,
    s.p + s.offset * s.n,
    [&](const LightSample& ls)
    {
      const float c = glm::dot(n, ls.wi);
      return c > 0.0f ? ls.Li * (c * kInvPi) : glm::vec3(0.0f);
    });
}

/// One sample of the path tracer with lit surfaces (see the top of this file).
template<typename Medium>
AMRDM_HD SampleResult pathTraceWithSurfaces(const TraceContext<Medium>& ctx,
  const Ray& cameraRay,
  float maxT)
{
  const RenderParams& params = ctx.params;
  const bool volume = drawsVolume(params);
  SampleResult out;
  SurfaceHit s = traceSurface(ctx, cameraRay, 0.0f, maxT);
  CameraRayEstimate camera; // no volume: transmittance 1, no vertex
  if (volume)
  {
    camera = estimateCameraRay(ctx, cameraRay, s.hit ? s.t : maxT);
  }
  const float W = camera.transmittance;
  out.alpha = s.hit ? 1.0f : 1.0f - W;
  out.L = camera.singleScatter;
  const glm::vec3 surfaceWeight = s.hit ? W * s.albedo : glm::vec3(0.0f);
  if (maxComponent(surfaceWeight) > 0.0f)
  {
    out.L += surfaceWeight * surfaceDirectLight(ctx, s);
  }
  const glm::vec3 mediumWeight = camera.collision.hit
                                   ? camera.collisionWeight * camera.collision.medium.albedo
                                   : glm::vec3(0.0f);
  const float wm = maxComponent(mediumWeight), ws = maxComponent(surfaceWeight);
  if (!(wm + ws > 0.0f) || params.maxBounces <= 0)
  {
    return out;
  }
  // The vertex the path continues from (no random number when only one has weight).
  const float pm = wm / (wm + ws);
  const bool fromSurface = ws > 0.0f && (!(wm > 0.0f) || !(ctx.rng.next() < pm));
  bool onSurface = fromSurface;
  glm::vec3 beta = fromSurface ? surfaceWeight / (1.0f - pm) : mediumWeight / pm;
  // Roulette reference: the vertex's weight before its albedo (as the volume path tracer).
  const float reference =
    glm::max(fromSurface ? W / (1.0f - pm) : camera.collisionWeight / pm, 1e-30f);
  Collision c = camera.collision;
  Ray ray = cameraRay;
  for (int bounce = 0; bounce < params.maxBounces; ++bounce)
  {
    if (bounce >= params.rouletteStartBounce)
    {
      const float survive = glm::min(1.0f, maxComponent(beta) / reference);
      if (ctx.rng.next() >= survive)
      {
        break;
      }
      beta /= survive;
    }
    const glm::vec2 u = bounce == 0 ? ctx.rng.ld2(kLdFirstDirection) : ctx.rng.next2();
    if (onSurface)
    {
      ray.o = s.p + s.offset * s.n;
      ray.d = cosineSampleHemisphere(s.n, u); // weight BRDF cos / pdf = albedo (in beta)
    }
    else
    {
      float pdf;
      ray.o = c.p;
      ray.d = hgSample(params.anisotropy, ray.d, u, pdf); // weight phase / pdf = 1
    }
    s = traceSurface(ctx, ray, 0.0f, kInfinity);
    c = volume ? ctx.freeFlight(ray, s.hit ? s.t : kInfinity) : Collision();
    if (c.hit)
    {
      beta *= c.medium.albedo;
      onSurface = false;
    }
    else if (s.hit)
    {
      beta *= s.albedo;
      onSurface = true;
    }
    else
    {
      out.L += beta * params.ambient;
      break;
    }
    if (!(maxComponent(beta) > 0.0f))
    {
      break;
    }
    out.L += beta * (onSurface ? surfaceDirectLight(ctx, s) : directLight(ctx, c.p, ray.d));
  }
  return out;
}

} // namespace amrdm
