// One sample of one pixel with the integrator fixed at compile time (renderSampleWith, one GPU
// kernel per integrator) or chosen at run time (renderSample, RenderParams::integrator), plus the
// debug views. The per-sample entry point of every renderer (PixelSamples.h sums a pass of them).
// Host/device code.
#pragma once

#include "core/Camera.h"
#include "sampling/Media.h"
#include "transport/PathTracer.h"
#include "transport/RayMarcher.h"

namespace amrdm
{

/// Debug colour of the primitive at world point p: gridlet dual cells as a checkerboard
/// (white / dark blue), tets red, pyramids green, wedges blue, hexes orange, miss black.
AMRDM_HD glm::vec3 primitiveColor(const DualMeshMedium& medium, const glm::vec3& p, TraceCounters& counters)
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
    const glm::ivec3 ijk = g.lower +
      glm::ivec3(c % g.dims.x, (c / g.dims.x) % g.dims.y, c / (g.dims.x * g.dims.y));
    return ((ijk.x + ijk.y + ijk.z) & 1) ? glm::vec3(1.0f) : glm::vec3(0.1f, 0.15f, 0.5f);
  }
  switch (type)
  {
    case PrimTet:
      return glm::vec3(0.9f, 0.1f, 0.1f);
    case PrimPyramid:
      return glm::vec3(0.1f, 0.8f, 0.1f);
    case PrimWedge:
      return glm::vec3(0.2f, 0.4f, 1.0f);
    default:
      return glm::vec3(1.0f, 0.55f, 0.0f);
  }
}

/// Analytic media have no primitives: white.
template <typename Medium>
AMRDM_HD glm::vec3 primitiveColor(const Medium&, const glm::vec3&, TraceCounters&)
{
  return glm::vec3(1.0f);
}

/// Heat ramp black -> red -> yellow -> white over x in [0, 1] (clamped).
AMRDM_HD glm::vec3 heatRamp(float x)
{
  x = glm::clamp(x, 0.0f, 1.0f) * 3.0f;
  return glm::vec3(glm::min(x, 1.0f), glm::clamp(x - 1.0f, 0.0f, 1.0f), glm::clamp(x - 2.0f, 0.0f, 1.0f));
}

/// Sample `sample` (in pass `frame`) of pixel (px, py) with integrator I, fixed at compile time
/// (the GPU instantiates one kernel per integrator, so the path tracer does not pay for the
/// registers of the others): camera ray with jitter, then the integrator over [minT, maxT]
/// (distances along the unit ray direction: maxT is the per-pixel depth clip, kInfinity for none;
/// minT > 0 moves the camera ray's origin to ray.at(minT), e.g. for clipping planes; minT >= maxT
/// gives an empty sample). Only the camera ray is clipped; scattered and shadow rays see the whole
/// medium. Random stream keyed by (pixel, sample, frame, params.seed).
template <IntegratorType I, typename Medium>
AMRDM_HD SampleResult renderSampleWith(const Medium& medium, const MajorantGridView& grid,
  const RenderParams& params, int px, int py, std::uint32_t sample, std::uint32_t frame, float maxT,
  TraceCounters& counters, float minT = 0.0f)
{
  const std::uint64_t pixel = std::uint64_t(py) * std::uint64_t(params.width) + std::uint64_t(px);
  Rng rng(pixel, sample, frame, params.seed);
  counters.lastPrimitive = ~0u; // no sampling state carried over from another pixel or sample
  const glm::vec2 jitter = rng.next2(); // drawn either way: the streams do not depend on it
  Ray ray = generateCameraRay(params.camera, params.width, params.height, px, py,
    params.pixelJitter ? jitter : glm::vec2(0.5f));
  if (!(minT < maxT))
  {
    return SampleResult();
  }
  if (minT > 0.0f)
  {
    ray.o = ray.at(minT);
    maxT -= minT;
  }
  if constexpr (I == IntegratorType::SingleScatter)
  {
    return traceSingleScatter(medium, grid, params, ray, maxT, rng, counters);
  }
  else if constexpr (I == IntegratorType::RayMarch)
  {
    return rayMarch(medium, grid, params, ray, maxT, rng.next(), counters);
  }
  else if constexpr (I == IntegratorType::DebugPrimitive)
  {
    SampleResult r;
    const Collision c =
      sampleFreeFlight(medium, grid, ray, 0.0f, maxT, rng, params.maxStepsPerWalk, counters);
    if (c.hit)
    {
      r.L = primitiveColor(medium, c.p, counters);
      r.alpha = 1.0f;
    }
    return r;
  }
  else if constexpr (I == IntegratorType::DebugCost)
  {
    TraceCounters cost;
    tracePath(medium, grid, params, ray, maxT, rng, cost);
    SampleResult r;
    r.L = heatRamp(float(cost.steps + cost.primitiveTests) / params.heatMapScale);
    r.alpha = 1.0f;
    counters.steps += cost.steps;
    counters.primitiveTests += cost.primitiveTests;
    counters.stepLimitHits += cost.stepLimitHits;
    counters.majorantViolations += cost.majorantViolations;
    return r;
  }
  else
  {
    return tracePath(medium, grid, params, ray, maxT, rng, counters);
  }
}

/// renderSampleWith() with the integrator chosen at run time (params.integrator).
template <typename Medium>
AMRDM_HD SampleResult renderSample(const Medium& medium, const MajorantGridView& grid,
  const RenderParams& params, int px, int py, std::uint32_t sample, std::uint32_t frame, float maxT,
  TraceCounters& counters, float minT = 0.0f)
{
  switch (params.integrator)
  {
    case IntegratorType::SingleScatter:
      return renderSampleWith<IntegratorType::SingleScatter>(
        medium, grid, params, px, py, sample, frame, maxT, counters, minT);
    case IntegratorType::RayMarch:
      return renderSampleWith<IntegratorType::RayMarch>(
        medium, grid, params, px, py, sample, frame, maxT, counters, minT);
    case IntegratorType::DebugPrimitive:
      return renderSampleWith<IntegratorType::DebugPrimitive>(
        medium, grid, params, px, py, sample, frame, maxT, counters, minT);
    case IntegratorType::DebugCost:
      return renderSampleWith<IntegratorType::DebugCost>(
        medium, grid, params, px, py, sample, frame, maxT, counters, minT);
    default:
      return renderSampleWith<IntegratorType::PathTracer>(
        medium, grid, params, px, py, sample, frame, maxT, counters, minT);
  }
}

} // namespace amrdm
