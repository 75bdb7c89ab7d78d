// The path tracer with isosurfaces as surfaces (transport/SurfaceHits.h), for BlendMode
// Isosurface (the surfaces alone: no volume) and for EmbedIsosurfaces (the surfaces inside the
// Composite volume). Integrate<PathTracer> (transport/PathTracer.h) hands such frames here.
//
// A surface reflects with the BRDF f = (1 - ks) albedo / pi + ks (p + 2) / (2 pi) (n.h)^p:
// albedo = the transfer function's colour at its value (VTK colours isosurfaces so), opacity =
// the transfer function's opacity there (an alpha surface below 1: SurfaceHits.h). The specular
// lobe (normalised Blinn-Phong, white as VTK's specular colour) is optional: ks =
// RenderParams::specularCoefficient and p = specularPower (vtkVolumeProperty's Specular and
// SpecularPower) when gradientShading (vtkVolumeProperty's Shade) is on; off, ks = 0 (Lambertian;
// docs/ISOSURFACES.md).
//
// Estimator (per sample):
//  - the camera ray stops at the first surface it is accepted by (traceSurface), at t_s (maxT
//    if none); with a volume, its part [0, t_s] is estimated by the volume path tracer's
//    camera walk (estimateCameraRay: transmittance W, the lights' single scattering, a vertex in
//    the medium with weight sum w), so the volume in front of a surface attenuates it by W;
//  - the surface: next-event estimation x W: f x Li x cos x the shadow ray's transmittance
//    (shadowTransmittance: the surfaces' prod (1 - opacity) times the volume's ratio tracking:
//    a surface shadows the volume and the volume shadows the surface);
//  - the path continues from ONE of the two vertices (the medium's, the surface's), chosen
//    with probability proportional to its weight (sum w x albedo, W x the surface's
//    reflectance), divided by that probability; at a surface a cosine-weighted direction
//    (weight pi f: the albedo without the specular lobe), in the medium the phase function;
//    each next segment ends at the next surface it is accepted by or at the next real collision
//    before it (delta tracking over [0, t_s]), with NEE at either; an escaping path sees the
//    ambient environment. Russian roulette as the volume path tracer.
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

/// The surface's specular lobe: ks and p (both 0 without gradientShading: Lambertian).
struct SurfaceLobe
{
  float ks = 0.0f;
  float power = 0.0f;
};

AMRDM_HD SurfaceLobe surfaceLobe(const RenderParams& params)
{
  SurfaceLobe lobe;
  if (params.gradientShading)
  {
    lobe.ks = glm::clamp(params.specularCoefficient, 0.0f, 1.0f);
    lobe.power = glm::max(params.specularPower, 0.0f);
  }
  return lobe;
}

/// pi x the BRDF for light arriving along wi and leaving along wo (both away from the surface,
/// on the normal's side): the weight of a cosine-sampled direction; the albedo exactly when
/// ks = 0.
AMRDM_HD glm::vec3 surfaceWeight(const SurfaceHit& s,
  const SurfaceLobe& lobe,
  const glm::vec3& wo,
  const glm::vec3& wi)
{
  if (!(lobe.ks > 0.0f))
  {
    return s.albedo;
  }
  const glm::vec3 h = glm::normalize(wo + wi);
  const float c = glm::max(0.0f, glm::dot(s.n, h));
  const float specular = lobe.ks * (lobe.power + 2.0f) * 0.5f * std::pow(c, lobe.power);
  return (1.0f - lobe.ks) * s.albedo + glm::vec3(specular);
}

/// A bound on the surface's reflectance (the choice between the camera ray's two vertices).
AMRDM_HD float surfaceReflectance(const SurfaceHit& s, const SurfaceLobe& lobe)
{
  return (1.0f - lobe.ks) * maxComponent(s.albedo) + lobe.ks;
}

/// Next-event estimation at a surface seen along wo (pointing away from it): sum over lights of
/// f x Li x cos x the shadow ray's transmittance (one shadow ray, directLightWith): the
/// reflected radiance. Lights behind the surface (cos <= 0) reflect nothing.
template<typename Medium>
AMRDM_HD glm::vec3 surfaceDirectLight(const TraceContext<Medium>& ctx,
  const SurfaceHit& s,
  const SurfaceLobe& lobe,
  const glm::vec3& wo)
{
  return directLightWith(ctx,
    s.p + s.offset * s.n,
    [&](const LightSample& ls)
    {
      const float c = glm::dot(s.n, ls.wi);
      return c > 0.0f ? ls.Li * surfaceWeight(s, lobe, wo, ls.wi) * (c * kInvPi) : glm::vec3(0.0f);
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
  const SurfaceLobe lobe = surfaceLobe(params);
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
  const float ws = s.hit ? W * surfaceReflectance(s, lobe) : 0.0f;
  if (ws > 0.0f)
  {
    out.L += W * surfaceDirectLight(ctx, s, lobe, -cameraRay.d);
  }
  const glm::vec3 mediumWeight = camera.collision.hit
                                   ? camera.collisionWeight * camera.collision.medium.albedo
                                   : glm::vec3(0.0f);
  const float wm = maxComponent(mediumWeight);
  if (!(wm + ws > 0.0f) || params.maxBounces <= 0)
  {
    return out;
  }
  // The vertex the path continues from (no random number when only one has weight).
  const float pm = wm / (wm + ws);
  bool onSurface = ws > 0.0f && (!(wm > 0.0f) || !(ctx.rng.next() < pm));
  // At a surface beta leaves out the BRDF, applied with the direction it samples.
  glm::vec3 beta = onSurface ? glm::vec3(W / (1.0f - pm)) : mediumWeight / pm;
  // Roulette reference: the vertex's weight before its albedo (as the volume path tracer).
  const float reference =
    glm::max(onSurface ? W / (1.0f - pm) : camera.collisionWeight / pm, 1e-30f);
  Collision c = camera.collision;
  Ray ray = cameraRay;
  for (int bounce = 0; bounce < params.maxBounces; ++bounce)
  {
    if (bounce >= params.rouletteStartBounce)
    {
      const float survive = glm::min(
        1.0f, maxComponent(beta) * (onSurface ? surfaceReflectance(s, lobe) : 1.0f) / reference);
      if (ctx.rng.next() >= survive)
      {
        break;
      }
      beta /= survive;
    }
    const glm::vec2 u = bounce == 0 ? ctx.rng.ld2(kLdFirstDirection) : ctx.rng.next2();
    if (onSurface)
    {
      const glm::vec3 wo = -ray.d;
      ray.o = s.p + s.offset * s.n;
      ray.d = cosineSampleHemisphere(s.n, u);
      beta *= surfaceWeight(s, lobe, wo, ray.d); // BRDF cos / pdf = pi f
    }
    else
    {
      float pdf;
      ray.o = c.p;
      ray.d = hgSample(params.anisotropy, ray.d, u, pdf); // weight phase / pdf = 1
    }
    if (!(maxComponent(beta) > 0.0f))
    {
      break;
    }
    s = traceSurface(ctx, ray, 0.0f, kInfinity);
    c = volume ? ctx.freeFlight(ray, s.hit ? s.t : kInfinity) : Collision();
    onSurface = !c.hit && s.hit;
    if (c.hit)
    {
      beta *= c.medium.albedo;
      if (!(maxComponent(beta) > 0.0f))
      {
        break;
      }
      out.L += beta * directLight(ctx, c.p, ray.d);
    }
    else if (s.hit)
    {
      out.L += beta * surfaceDirectLight(ctx, s, lobe, -ray.d);
    }
    else
    {
      out.L += beta * params.ambient;
      break;
    }
  }
  return out;
}

} // namespace amrdm
