// Next-event estimation to the delta lights: ONE light per scattering event, chosen with
// probability proportional to its unshadowed contribution at the point (light x phase, summed
// over RGB), and one ratio-tracked shadow ray to it, weighted by 1 / that probability. Unbiased
// like a shadow ray to every light, at the cost of one: with VTK's five-light kit that was five
// shadow rays per event, most of the path tracer's time. Host/device code.
#pragma once

#include "transport/PhaseFunction.h"
#include "transport/SurfaceHits.h"

namespace amrdm
{

/// Shadow rays are ratio-tracked against their majorant times this factor: against a tight
/// majorant ratio tracking is all or nothing (variance T (1 - T)); at 2x it is
/// exp(-tau 3/2) - T^2, 2.4x lower at T = 1/2, for twice the tentative collisions.
constexpr float kShadowMajorantScale = 2.0f;

AMRDM_HD float maxComponent(const glm::vec3& v)
{
  return glm::max(v.x, glm::max(v.y, v.z));
}

/// Estimate of the sum over lights of f(light sample) x transmittance at p (one shadow ray):
/// `contribution(const LightSample&) -> glm::vec3` is the unshadowed contribution (phase x Li
/// in the medium, BRDF x cos x Li at a surface). `uChoice` (optional): the uniform that chooses
/// the light (e.g. from the pixel's low-discrepancy sequence); without it the stream draws one
/// when more than one light contributes. `uShadowStart` (>= 0): the uniform of the shadow ray's
/// first free-flight step. The shadow ray is blocked by the frame's lit surfaces
/// (shadowTransmittance, transport/SurfaceHits.h).
template<typename Medium, typename Contribution>
AMRDM_HD glm::vec3 directLightWith(const TraceContext<Medium>& ctx,
  const glm::vec3& p,
  Contribution&& contribution,
  const float* uChoice = nullptr,
  float uShadowStart = -1.0f)
{
  const RenderParams& params = ctx.params;
  const int n = params.numLights < kMaxLights ? params.numLights : kMaxLights;
  // Pass 1: the selection weights (no arrays: registers matter on the GPU).
  float total = 0.0f;
  int positive = 0, last = -1;
  for (int i = 0; i < n; ++i)
  {
    const glm::vec3 f = contribution(sampleLight(params.lights[i], p));
    const float w = f.x + f.y + f.z;
    if (w > 0.0f)
    {
      total += w;
      ++positive;
      last = i;
    }
  }
  if (!(total > 0.0f))
  {
    return glm::vec3(0.0f);
  }
  // Pass 2: the chosen light (no random number when only one light contributes).
  float u = positive > 1 ? (uChoice ? *uChoice : ctx.rng.next()) * total : 0.0f;
  for (int i = 0; i < n; ++i)
  {
    const LightSample ls = sampleLight(params.lights[i], p);
    const glm::vec3 f = contribution(ls);
    const float w = f.x + f.y + f.z;
    if (!(w > 0.0f))
    {
      continue;
    }
    if (u < w || i == last)
    {
      Ray shadow;
      shadow.o = p;
      shadow.d = ls.wi;
      const float T =
        shadowTransmittance(ctx, shadow, ls.distance, kShadowMajorantScale, uShadowStart);
      return f * (T * (total / w));
    }
    u -= w;
  }
  return glm::vec3(0.0f); // not reached: `last` is always chosen at the latest
}

/// Estimate of the sum over lights of phase x Li x transmittance at p, for a path travelling
/// along dIn (directLightWith: one shadow ray).
template<typename Medium>
AMRDM_HD glm::vec3 directLight(const TraceContext<Medium>& ctx,
  const glm::vec3& p,
  const glm::vec3& dIn,
  const float* uChoice = nullptr,
  float uShadowStart = -1.0f)
{
  const float g = ctx.params.anisotropy;
  // Light travels along -wi, then scatters into -dIn: cos(theta) = dot(wi, dIn).
  return directLightWith(
    ctx,
    p,
    [&](const LightSample& ls) { return ls.Li * hgPhase(g, glm::dot(ls.wi, dIn)); },
    uChoice,
    uShadowStart);
}

} // namespace amrdm
