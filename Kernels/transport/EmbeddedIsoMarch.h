// EmbedIsosurfaces for the integrators that composite front to back (the ray marcher, trait
// `embedsIsosurfaces` with `blendModes`, render/IntegratorList.h): the camera ray is cut at its
// isosurface crossings (transport/Isosurface.h: exact), each piece of volume drawn by the
// integrator itself on the piece, each crossing composited behind it with the transfer
// function's colour and opacity at its value (shaded as the Isosurface blend mode shades), in
// depth order: C += (1 - A) c, A += (1 - A) a, until A reaches params.earlyTermination. The
// pieces keep the camera ray's true origin (Ray::tCamera), so the ray marcher's uniform lattice
// is the one of the whole ray. At most kMaxIsoLayers crossings; past them the volume alone.
// Host/device code.
#pragma once

#include "transport/PathTracer.h"

namespace amrdm
{

/// Whether the frame composites isosurfaces into the volume with integrator I (Composite,
/// embedIsosurfaces, values given, and the integrator's `embedsIsosurfaces` trait).
template<IntegratorType I>
AMRDM_HD bool compositesEmbeddedSurfaces(const RenderParams& params)
{
  return integratorInfo(I).embedsIsosurfaces && params.blendMode == BlendMode::Composite &&
         params.embedIsosurfaces && params.numIsoValues > 0;
}

/// Integrate<I>::sample on the pieces between the surfaces along `ray`, composited in depth order
/// with the surfaces; `shade(gradient, rgb, viewDir) -> rgb` shades a surface.
template<IntegratorType I, typename Medium, typename Shade>
AMRDM_HD SampleResult compositeEmbeddedSurfaces(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float maxT,
  Shade&& shade)
{
  const RenderParams& params = ctx.params;
  glm::vec3 C(0.0f);
  float A = 0.0f;
  float t = 0.0f;
  // The volume over [t, tEnd]: the integrator on the piece, its origin moved along the ray.
  auto volume = [&](float tEnd)
  {
    if (!(tEnd > t))
    {
      return;
    }
    Ray piece = ray;
    piece.o = ray.at(t);
    piece.tCamera = ray.tCamera + t;
    const SampleResult v = Integrate<I>::sample(ctx, piece, tEnd - t);
    C += (1.0f - A) * v.L;
    A += (1.0f - A) * v.alpha;
  };
  bool more = true;
  forEachSurfaceCrossing(ctx,
    ray,
    0.0f,
    maxT,
    [&](const IsoHit& hit, const glm::vec4& c) -> bool
    {
      volume(hit.t);
      if (A >= params.earlyTermination)
      {
        more = false;
        return false;
      }
      const glm::vec3 rgb = shade(hit.gradient, glm::vec3(c), ray.d);
      C += (1.0f - A) * c.w * rgb;
      A += (1.0f - A) * c.w;
      t = hit.t + hit.skip;
      more = A < params.earlyTermination;
      return more;
    });
  if (more)
  {
    volume(maxT);
  }
  SampleResult out;
  out.L = C;
  out.alpha = A;
  return out;
}

} // namespace amrdm
