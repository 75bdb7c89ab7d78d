// What every integrator traces with, in one argument: the medium, its majorant grid, the
// (resolved) render parameters, the sample's random stream and its work counters. An integrator
// is Integrate<I>::sample(const TraceContext<Medium>&, const Ray&, float maxT)
// (render/IntegratorList.h); the walks it takes are freeFlight() and transmittance() below (the
// one walk() of DeltaTracking.h over walker(), cut at params.maxStepsPerWalk). Host/device code.
#pragma once

#include "render/RenderParams.h"
#include "transport/DeltaTracking.h"

namespace amrdm
{

template<typename Medium>
struct TraceContext
{
  const Medium& medium;
  MajorantGridView grid;
  const RenderParams& params;
  Rng& rng;                ///< the sample's stream (one per pixel, sample, pass and seed)
  TraceCounters& counters; ///< summed per pixel and pass by the renderer

  /// The walk context of this sample (DeltaTracking.h): cut at params.maxStepsPerWalk.
  AMRDM_HD WalkContext<Medium> walker() const
  {
    return walkContext(
      this->medium, this->grid, this->rng, this->params.maxStepsPerWalk, this->counters);
  }
  /// Delta tracking along `ray` over [0, tmax] (sampleFreeFlight).
  AMRDM_HD Collision freeFlight(const Ray& ray, float tmax) const
  {
    return sampleFreeFlight(this->walker(), ray, 0.0f, tmax);
  }
  /// Ratio-tracked transmittance along `ray` over [0, tmax] (estimateTransmittance), against
  /// the majorant times majorantScale; `firstU` (>= 0): the first step's uniform.
  AMRDM_HD float transmittance(const Ray& ray,
    float tmax,
    float majorantScale = 1.0f,
    float firstU = -1.0f) const
  {
    return estimateTransmittance(this->walker(), ray, 0.0f, tmax, majorantScale, firstU);
  }
};

/// The context of one sample (C++17 has no aggregate deduction for this shape).
template<typename Medium>
AMRDM_HD TraceContext<Medium> traceContext(const Medium& medium,
  const MajorantGridView& grid,
  const RenderParams& params,
  Rng& rng,
  TraceCounters& counters)
{
  return TraceContext<Medium>{ medium, grid, params, rng, counters };
}

} // namespace amrdm
