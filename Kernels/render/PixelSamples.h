// One pass of one pixel: params.samplesPerPass samples summed (and their squares) in double, the
// unit every renderer accumulates. The CPU renderer's tiles and the benchmark's loop
// (TiledPass.h) and the CUDA kernel (one thread per pixel) all call samplePixelWith<I>(), the
// integrator I chosen once per tile or launch (withIntegrator, render/IntegratorList.h); image()
// and varianceOfMean() come from these sums through accumulatedMean() / accumulatedVarianceOfMean()
// (Renderer.h). Host/device code.
#pragma once

#include "transport/Integrators.h"

namespace amrdm
{

/// Sums over one pass of one pixel (premultiplied RGBA; double: a float running sum of many
/// samples loses bits).
struct PixelSamples
{
  glm::dvec4 sum{ 0.0 };
  glm::dvec4 sumSq{ 0.0 };
};

/// params.samplesPerPass samples of pixel (x, y) in pass `frame` with integrator I, over
/// [startT, maxT] along each camera ray (see renderSampleWith).
template<IntegratorType I, typename Medium>
AMRDM_HD PixelSamples samplePixelWith(const Medium& medium,
  const MajorantGridView& grid,
  const RenderParams& params,
  int x,
  int y,
  std::uint32_t frame,
  float maxT,
  float startT,
  TraceCounters& counters)
{
  PixelSamples p;
  for (int s = 0; s < params.samplesPerPass; ++s)
  {
    const SampleResult r = renderSampleWith<I>(
      medium, grid, params, x, y, std::uint32_t(s), frame, maxT, counters, startT);
    const glm::dvec4 v(glm::vec4(r.L, r.alpha));
    p.sum += v;
    p.sumSq += v * v;
  }
  return p;
}

} // namespace amrdm
