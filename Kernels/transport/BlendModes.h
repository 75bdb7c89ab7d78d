// The non-composite blend modes of vtkVolumeMapper (render/BlendModeList.h), drawn by the
// integrators with the `blendModes` trait (render/IntegratorList.h: the ray marcher) on the same
// camera rays, CPU and CUDA alike:
//   MaximumIntensity / MinimumIntensity: the largest / smallest value of the samples along the
//     ray; colour and opacity are the transfer function's at that value (premultiplied);
//   AverageIntensity: grey, the mean of opacity(v) v' over the samples whose value lies in
//     [averageRangeLo, averageRangeHi], each weighted by its length, v' = the value's position
//     in the transfer function's domain (0..1, VTK: in the scalar range), alpha 1 where a sample
//     counted;
//   Additive: grey, the integral of opacity(v) v' ds / unitDistance clamped to 1 (VTK sums per
//     sample; this is that sum at a sample distance of one unit distance, but independent of
//     the step), alpha 1 where the ray met data;
//   Isosurface: the exact crossings of the interpolant with each value (transport/Isosurface.h),
//     front to back, each with the transfer function's colour and opacity at its value, shaded
//     with the analytic gradient when gradientShading is on, at most kMaxIsoLayers per ray;
//   Slice: the interpolant where the ray meets the plane, colour and opacity from the transfer
//     function (premultiplied), nothing where the plane has no data.
// The projection modes sample the ray marcher's lattice (the uniform step from the camera's eye,
// or the level-adaptive strata) over the macrocells that hold data (MajorantGridView::range),
// so they do not depend on the transfer function's opacity to find data. Host/device code.
#pragma once

#include "transport/EmbeddedIsoMarch.h"
#include "transport/Isosurface.h"
#include "transport/MarchLattice.h"
#include "transport/PathTracer.h"
#include "transport/RayMarcher.h" // shadeSurface

#include <cmath>
#include <type_traits>
#include <utility>

namespace amrdm
{

/// Calls visit(value, length) for each sample with data along `ray` over [0, tmax], on the ray
/// marcher's lattice (see rayMarch, transport/RayMarcher.h), until visit returns false or
/// params.maxStepsPerWalk samples were taken. Macrocells without data are skipped.
template<typename Medium, typename Visit>
AMRDM_HD void marchValues(const TraceContext<Medium>& ctx,
  const Ray& ray,
  float tmax,
  float jitter,
  Visit&& visit)
{
  const RenderParams& params = ctx.params;
  const MajorantGridView& grid = ctx.grid;
  const float step = params.stepSize;
  if (!(step > 0.0f))
  {
    return;
  }
  const float invStep = 1.0f / step;
  int steps = 0;
  auto sampleAt = [&](float t, float length) -> bool
  {
    if (steps >= params.maxStepsPerWalk)
    {
      ++ctx.counters.stepLimitHits;
      return false;
    }
    ++steps;
    ++ctx.counters.steps;
    float v = 0.0f;
    bool found;
    {
      const RayHintSlot slot(ctx.counters, t + ray.tCamera, invStep);
      found = ctx.medium.value(ray.at(t), v, ctx.counters);
    }
    return !found || visit(v, length);
  };
  marchLattice(
    grid,
    ray,
    tmax,
    step,
    params.samplesPerCell,
    jitter,
    [&](const MajorantSegment& seg)
    { return grid.range && !(grid.range[seg.cell].x <= grid.range[seg.cell].y); },
    sampleAt);
}

/// The value's position in the transfer function's domain, 0..1 (v' of the grey modes).
AMRDM_HD float normalizedValue(const TransferFunctionView& tf, float v)
{
  return tf.size > 1 ? tfCoordinate(tf, v) / float(tf.size - 1) : 0.0f;
}

/// MaximumIntensity, MinimumIntensity, AverageIntensity, Additive.
template<typename Medium>
AMRDM_HD SampleResult projectRay(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
{
  const RenderParams& params = ctx.params;
  const TransferFunctionView& tf = ctx.medium.tf;
  const BlendMode mode = params.blendMode;
  bool any = false;
  float extreme = 0.0f;
  double sum = 0.0, weight = 0.0;
  marchValues(ctx,
    ray,
    maxT,
    ctx.rng.next(),
    [&](float v, float length)
    {
      if (mode == BlendMode::MaximumIntensity || mode == BlendMode::MinimumIntensity)
      {
        const bool better = mode == BlendMode::MaximumIntensity ? v > extreme : v < extreme;
        extreme = !any || better ? v : extreme;
        any = true;
        return true;
      }
      if (mode == BlendMode::AverageIntensity &&
          !(params.averageRangeLo <= v && v <= params.averageRangeHi))
      {
        return true;
      }
      any = true;
      sum += double(tfLookup(tf, v).w * normalizedValue(tf, v)) * double(length);
      weight += double(length);
      return true;
    });
  SampleResult out;
  if (!any)
  {
    return out;
  }
  if (mode == BlendMode::MaximumIntensity || mode == BlendMode::MinimumIntensity)
  {
    const glm::vec4 c = tfLookup(tf, extreme);
    out.L = glm::vec3(c) * c.w;
    out.alpha = c.w;
    return out;
  }
  const double grey = mode == BlendMode::AverageIntensity ? (weight > 0.0 ? sum / weight : 0.0)
                                                          : sum / double(ctx.medium.unitDistance());
  out.L = glm::vec3(float(glm::clamp(grey, 0.0, 1.0)));
  out.alpha = 1.0f;
  return out;
}

/// Slice: the plane (params.sliceOrigin, params.sliceNormal) where the ray meets it in [0, maxT].
template<typename Medium>
AMRDM_HD SampleResult sliceRay(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
{
  SampleResult out;
  const glm::vec3 n = ctx.params.sliceNormal;
  const float denom = glm::dot(ray.d, n);
  if (denom == 0.0f || !(glm::dot(n, n) > 0.0f))
  {
    return out;
  }
  const float t = glm::dot(ctx.params.sliceOrigin - ray.o, n) / denom;
  float v = 0.0f;
  if (!(t >= 0.0f && t <= maxT) || !ctx.medium.value(ray.at(t), v, ctx.counters))
  {
    return out;
  }
  const glm::vec4 c = tfLookup(ctx.medium.tf, v);
  out.L = glm::vec3(c) * c.w;
  out.alpha = c.w;
  return out;
}

/// Isosurface: the crossings with params.isoValues, front to back.
template<typename Medium>
AMRDM_HD SampleResult isoRay(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
{
  const RenderParams& params = ctx.params;
  SampleResult out;
  const int numIso = glm::clamp(params.numIsoValues, 0, kMaxIsoValues);
  float t = 0.0f, A = 0.0f;
  glm::vec3 C(0.0f);
  for (int layer = 0; layer < kMaxIsoLayers && t <= maxT && A < params.earlyTermination; ++layer)
  {
    const IsoHit hit = findIsoHit(
      ctx.medium, ctx.grid, ray, t, maxT, params.isoValues, numIso, params.stepSize, ctx.counters);
    if (!hit.hit())
    {
      break;
    }
    const glm::vec4 c = tfLookup(ctx.medium.tf, params.isoValues[hit.index]);
    glm::vec3 rgb(c);
    if (params.gradientShading)
    {
      rgb = shadeSurface(params, hit.gradient, rgb, ray.d);
    }
    C += (1.0f - A) * c.w * rgb;
    A += (1.0f - A) * c.w;
    t = hit.t + hit.skip;
  }
  out.L = C;
  out.alpha = A;
  return out;
}

/// The sample of a non-composite blend mode (Composite: empty; the integrator draws it).
template<typename Medium>
AMRDM_HD SampleResult renderBlend(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
{
  switch (ctx.params.blendMode)
  {
    case BlendMode::MaximumIntensity:
    case BlendMode::MinimumIntensity:
    case BlendMode::AverageIntensity:
    case BlendMode::Additive:
      return projectRay(ctx, ray, maxT);
    case BlendMode::Isosurface:
      return isoRay(ctx, ray, maxT);
    case BlendMode::Slice:
      return sliceRay(ctx, ray, maxT);
    default:
      return SampleResult();
  }
}

/// Whether Medium maps values through a transfer function of its own (`tf`): the media the
/// blend modes can colour (the dual mesh, the benchmarks' and tests' field media).
template<typename Medium, typename = void>
struct HasTransferFunction : std::false_type
{
};
template<typename Medium>
struct HasTransferFunction<Medium, std::void_t<decltype(std::declval<const Medium&>().tf)>>
  : std::true_type
{
};

/// Integrate<I>::sample, or renderBlend where integrator I draws blend modes (its `blendModes`
/// trait), the medium has a transfer function and params.blendMode is not Composite. Resolved
/// at compile time: integrators without the trait carry no blend-mode code.
template<IntegratorType I,
  typename Medium,
  bool Blend = integratorInfo(I).blendModes&& HasTransferFunction<Medium>::value>
struct SampleWithBlendMode
{
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
  {
    return Integrate<I>::sample(ctx, ray, maxT);
  }
};
template<IntegratorType I, typename Medium>
struct SampleWithBlendMode<I, Medium, true>
{
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
  {
    if (compositesEmbeddedSurfaces<I>(ctx.params)) // EmbedIsosurfaces: EmbeddedIsoMarch.h
    {
      return compositeEmbeddedSurfaces<I>(ctx,
        ray,
        maxT,
        [&](const glm::vec3& g, const glm::vec3& rgb, const glm::vec3& d)
        { return ctx.params.gradientShading ? shadeSurface(ctx.params, g, rgb, d) : rgb; });
    }
    return ctx.params.blendMode == BlendMode::Composite ? Integrate<I>::sample(ctx, ray, maxT)
                                                        : renderBlend(ctx, ray, maxT);
  }
};

} // namespace amrdm
