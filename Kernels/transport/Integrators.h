// One sample of one pixel with the integrator fixed at compile time (renderSampleWith, one GPU
// kernel per integrator): the camera ray, then Integrate<I>::sample with the sample's
// TraceContext. The per-sample entry point of every renderer (PixelSamples.h sums a pass of
// them; the one run-time switch over the integrators is withIntegrator, render/IntegratorList.h).
// The integrators are registered in render/IntegratorList.h; each one's header is included here.
// Host/device code.
#pragma once

#include "core/Camera.h"
#include "sampling/Media.h"
#include "render/IntegratorList.h"
#include "transport/BlendModes.h"
#include "transport/DebugViews.h"
#include "transport/PathTracer.h"
#include "transport/RayMarcher.h"

namespace amrdm
{

/// Sample `sample` (in pass `frame`) of pixel (px, py) with integrator I, fixed at compile time
/// (the GPU instantiates one kernel per integrator, so the path tracer does not pay for the
/// registers of the others): camera ray with jitter, then the integrator over [minT, maxT]
/// (distances along the unit ray direction: maxT is the per-pixel depth clip, kInfinity for none;
/// minT > 0 moves the camera ray's origin to ray.at(minT), e.g. for clipping planes; minT >= maxT
/// gives an empty sample). Integrators with the `blendModes` trait draw params.blendMode's
/// non-composite modes instead (transport/BlendModes.h). Only the camera ray is clipped;
/// scattered and shadow rays see the whole medium. Random stream keyed by (pixel, sample, frame,
/// params.seed); its low-discrepancy pairs (core/Random.h's LdPair) by (pixel, params.seed) at
/// sample number frame x samplesPerPass + sample.
template<IntegratorType I, typename Medium>
AMRDM_HD SampleResult renderSampleWith(const Medium& medium,
  const MajorantGridView& grid,
  const RenderParams& params,
  int px,
  int py,
  std::uint32_t sample,
  std::uint32_t frame,
  float maxT,
  TraceCounters& counters,
  float minT = 0.0f)
{
  const std::uint64_t pixel = std::uint64_t(py) * std::uint64_t(params.width) + std::uint64_t(px);
  Rng rng(pixel, sample, frame, params.seed);
  // The pixel's low-discrepancy pairs at its sample number across passes (passes of equal size).
  rng.lowDiscrepancy(frame * std::uint32_t(params.samplesPerPass) + sample,
    std::uint32_t(mix64(mix64(std::uint64_t(params.seed) + 0x632be59bd9b4e019ull) ^ pixel)));
  counters.lastPrimitive = ~0u; // no sampling state carried over from another pixel or sample
  counters.lastOuterPrimitive = ~0u;
  const glm::vec2 jitter = rng.ld2(kLdPixelJitter); // drawn either way
  Ray ray = generateCameraRay(params.camera,
    params.width,
    params.height,
    px,
    py,
    params.pixelJitter ? jitter : glm::vec2(0.5f));
  if (params.clipToBox)
  {
    // Slab test of this very ray: neighbouring regions cut it at the same t (fmax/fmin skip
    // the NaN of a ray lying in a face plane).
    for (int a = 0; a < 3; ++a)
    {
      const float inv = 1.0f / ray.d[a];
      const float ta = (params.clipLo[a] - ray.o[a]) * inv;
      const float tb = (params.clipHi[a] - ray.o[a]) * inv;
      minT = fmaxf(minT, fminf(ta, tb));
      maxT = fminf(maxT, fmaxf(ta, tb));
    }
  }
  if (!(minT < maxT))
  {
    return SampleResult();
  }
  if (minT > 0.0f)
  {
    ray.o = ray.at(minT);
    ray.tCamera += minT;
    maxT -= minT;
  }
  return SampleWithBlendMode<I, Medium>::sample(
    traceContext(medium, grid, params, rng, counters), ray, maxT);
}

} // namespace amrdm
