// The debug views as integrators: the primitive at the first collision (gridlet dual cells as a
// checkerboard, one colour per element kind) and a heat map of the path tracer's work. Registered
// in render/IntegratorList.h like every integrator. Host/device code.
#pragma once

#include "sampling/Media.h"
#include "transport/PathTracer.h"

namespace amrdm
{

/// Debug colour of the primitive at world point p: gridlet dual cells as a checkerboard
/// (white / dark blue), elements by kind (mesh/ElementList.h: tets red, pyramids green, wedges
/// blue, hexes orange), miss black.
AMRDM_HD glm::vec3 primitiveColor(const DualMeshMedium& medium,
  const glm::vec3& p,
  TraceCounters& counters)
{
  float v;
  SampleHit hit;
  if (!medium.value(p, v, counters, &hit))
  {
    return glm::vec3(0.0f);
  }
  const std::uint32_t type = primType(hit.prim);
  if (type == PrimGridlet)
  {
    const GridletHeader& g = medium.mesh.gridlets[primIndex(hit.prim)];
    const int c = hit.cell < 0 ? 0 : hit.cell;
    const glm::ivec3 ijk =
      g.lower + glm::ivec3(c % g.dims.x, (c / g.dims.x) % g.dims.y, c / (g.dims.x * g.dims.y));
    return ((ijk.x + ijk.y + ijk.z) & 1) ? glm::vec3(1.0f) : glm::vec3(0.1f, 0.15f, 0.5f);
  }
  switch (type)
  {
#define AMRDM_ELEMENT_COLOR(kind, name, member, corners, sample, r, g, b)                          \
  case Prim##kind:                                                                                 \
    return glm::vec3(r, g, b);
    AMRDM_ELEMENTS(AMRDM_ELEMENT_COLOR)
#undef AMRDM_ELEMENT_COLOR
    default:
      return glm::vec3(1.0f, 0.0f, 1.0f); // magenta: a type outside mesh/ElementList.h
  }
}

/// Analytic media have no primitives: white.
template<typename Medium>
AMRDM_HD glm::vec3 primitiveColor(const Medium&, const glm::vec3&, TraceCounters&)
{
  return glm::vec3(1.0f);
}

/// Heat ramp black -> red -> yellow -> white over x in [0, 1] (clamped).
AMRDM_HD glm::vec3 heatRamp(float x)
{
  x = glm::clamp(x, 0.0f, 1.0f) * 3.0f;
  return glm::vec3(
    glm::min(x, 1.0f), glm::clamp(x - 1.0f, 0.0f, 1.0f), glm::clamp(x - 2.0f, 0.0f, 1.0f));
}

template<>
struct Integrate<IntegratorType::DebugPrimitive>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
  {
    SampleResult r;
    const Collision c = ctx.freeFlight(ray, maxT);
    if (c.hit)
    {
      r.L = primitiveColor(ctx.medium, c.p, ctx.counters);
      r.alpha = 1.0f;
    }
    return r;
  }
};

/// The path tracer's work (its own counters), as a heat map over params.heatMapScale.
template<>
struct Integrate<IntegratorType::DebugCost>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
  {
    TraceCounters cost;
    const TraceContext<Medium> costCtx{ ctx.medium, ctx.grid, ctx.params, ctx.rng, cost };
    Integrate<IntegratorType::PathTracer>::sample(costCtx, ray, maxT);
    SampleResult r;
    r.L = heatRamp(float(cost.steps + cost.primitiveTests) / ctx.params.heatMapScale);
    r.alpha = 1.0f;
    addWorkCounters(ctx.counters, cost);
    return r;
  }
};

} // namespace amrdm
