// Isosurfaces as surfaces of the path tracer (transport/SurfacePathTracer.h): which frames have
// them, the nearest surface a ray stops at, and the transmittance of a shadow ray through them.
// A surface is the exact crossing of the interpolant with one of params.isoValues
// (transport/Isosurface.h: findIsoHit), with VTK's colour and opacity for an isosurface: the
// transfer function's at its value. Opacity < 1 makes it an alpha (stochastic) surface: a ray
// stops at a crossing with probability = opacity and passes through otherwise (unbiased for the
// radiance; no random number when the opacity is 0 or 1), and a shadow ray is attenuated by
// prod (1 - opacity) over the crossings before the light (its exact expectation, no noise).
// Host/device code.
#pragma once

#include "transport/Isosurface.h"
#include "transport/TraceContext.h"

#include <type_traits>
#include <utility>

namespace amrdm
{

/// Whether Medium has a field with a transfer function to find isosurfaces in (`tf` and
/// `value(p, v, counters)`): the dual mesh and the analytic field media; the others (homogeneous
/// test media) draw the volume only.
template<typename Medium, typename = void>
struct HasIsoField : std::false_type
{
};
template<typename Medium>
struct HasIsoField<Medium,
  std::void_t<decltype(std::declval<const Medium&>().tf),
    decltype(std::declval<const Medium&>()
               .value(glm::vec3(0.0f), std::declval<float&>(), std::declval<TraceCounters&>()))>>
  : std::true_type
{
};

/// Whether the frame's surfaces are drawn by the path tracer as surfaces: BlendMode Isosurface
/// (surfaces alone, no volume) with an integrator that has the `litIsosurfaces` trait, or
/// embedIsosurfaces with Composite and the `embedsIsosurfaces` trait.
AMRDM_HD bool drawsLitSurfaces(const RenderParams& params)
{
  const IntegratorInfo& info = integratorInfo(params.integrator);
  return (params.blendMode == BlendMode::Isosurface && info.litIsosurfaces) ||
         (params.blendMode == BlendMode::Composite && params.embedIsosurfaces &&
           info.embedsIsosurfaces && params.numIsoValues > 0);
}

/// Whether the frame's volume scatters and absorbs (not in the path-traced Isosurface mode).
AMRDM_HD bool drawsVolume(const RenderParams& params)
{
  return params.blendMode != BlendMode::Isosurface;
}

/// Where a ray stops at a surface.
struct SurfaceHit
{
  bool hit = false;
  float t = kInfinity;
  glm::vec3 p{ 0.0f };      ///< the hit point
  glm::vec3 n{ 0.0f };      ///< unit normal facing the side the ray came from (two-sided)
  glm::vec3 albedo{ 0.0f }; ///< the transfer function's colour at the surface's value
  float offset = 0.0f;      ///< rays leaving the surface start at p + offset n
};

/// The opacity of the surface of value index k (the transfer function's, clamped to [0, 1]).
template<typename Medium>
AMRDM_HD glm::vec4 surfaceColor(const Medium& medium, const RenderParams& params, int k)
{
  const glm::vec4 c = tfLookup(medium.tf, params.isoValues[k]);
  return glm::vec4(glm::vec3(c), glm::clamp(c.w, 0.0f, 1.0f));
}

/// Calls visit(hit, colour) for each crossing of `ray` with the surfaces in (tFrom, tTo], front
/// to back, at most kMaxIsoLayers, until visit returns false.
template<typename Medium, typename Visit>
AMRDM_HD void forEachSurfaceCrossing(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float tFrom,
  float tTo,
  Visit&& visit)
{
  const RenderParams& params = ctx.params;
  const int numIso = glm::clamp(params.numIsoValues, 0, kMaxIsoValues);
  float t = tFrom;
  for (int layer = 0; layer < kMaxIsoLayers && numIso > 0 && t <= tTo; ++layer)
  {
    const IsoHit hit = findIsoHit(
      ctx.medium, ctx.grid, ray, t, tTo, params.isoValues, numIso, params.stepSize, ctx.counters);
    if (!hit.hit() || !visit(hit, surfaceColor(ctx.medium, params, hit.index)))
    {
      return;
    }
    t = hit.t + hit.skip;
  }
}

/// The surface `ray` stops at in [tFrom, tTo]: each crossing accepted with probability = its
/// opacity (one random number only where 0 < opacity < 1).
template<typename Medium>
AMRDM_HD SurfaceHit
traceSurface(const TraceContext<Medium>& ctx, const Ray& ray, float tFrom, float tTo)
{
  SurfaceHit s;
  forEachSurfaceCrossing(ctx,
    ray,
    tFrom,
    tTo,
    [&](const IsoHit& hit, const glm::vec4& c) -> bool
    {
      if (!(c.w > 0.0f) || (c.w < 1.0f && !(ctx.rng.next() < c.w)))
      {
        return true; // passes through this crossing
      }
      s.hit = true;
      s.t = hit.t;
      s.p = ray.at(hit.t);
      s.albedo = glm::vec3(c);
      const float len = glm::length(hit.gradient);
      s.n = len > 0.0f ? hit.gradient / len : -ray.d;
      s.n = glm::dot(s.n, ray.d) > 0.0f ? -s.n : s.n;
      // Past the crossing's own float noise: 4 skips (a thousandth of the primitive's cell per
      // skip) and the point's coordinates' rounding.
      const float scale = glm::max(std::fabs(s.p.x), glm::max(std::fabs(s.p.y), std::fabs(s.p.z)));
      s.offset = 4.0f * hit.skip + 1e-5f * scale;
      return false;
    });
  return s;
}

/// The transmittance of the surfaces along `ray` over [0, tTo]: prod (1 - opacity) over the
/// crossings (0 at the first opaque one).
template<typename Medium>
AMRDM_HD float surfaceTransmittance(const TraceContext<Medium>& ctx, const Ray& ray, float tTo)
{
  float T = 1.0f;
  forEachSurfaceCrossing(ctx,
    ray,
    0.0f,
    tTo,
    [&](const IsoHit&, const glm::vec4& c) -> bool
    {
      T *= 1.0f - c.w;
      return T > 0.0f;
    });
  return T;
}

/// The transmittance of a shadow ray over [0, tTo]: the surfaces' (where the frame has lit
/// surfaces) times the volume's (ratio tracking against the majorant x majorantScale, its first
/// step's uniform `firstU` >= 0 when given; where the frame has a volume). Without surfaces it
/// is the volume's ratio tracking alone, with the same random numbers as before surfaces existed.
template<typename Medium>
AMRDM_HD float shadowTransmittance(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float tTo,
  float majorantScale,
  float firstU)
{
  float T = 1.0f;
  if constexpr (HasIsoField<Medium>::value)
  {
    if (drawsLitSurfaces(ctx.params))
    {
      T = surfaceTransmittance(ctx, ray, tTo);
      if (!(T > 0.0f) || !drawsVolume(ctx.params))
      {
        return T;
      }
    }
  }
  return T * ctx.transmittance(ray, tTo, majorantScale, firstU);
}

} // namespace amrdm
