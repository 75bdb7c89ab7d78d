// The ray marcher's sample lattice, walked once for every integrator that samples along camera
// rays at discrete points (transport/RayMarcher.h: emission-absorption compositing;
// transport/BlendModes.h: the projection blend modes). Host/device code.
#pragma once

#include "accel/MajorantIterator.h"
#include "transport/DeltaTracking.h" // TraceCounters

#include <cmath>

namespace amrdm
{

/// While it lives, the lattice sample at camera distance T (samples `step` apart, invStep =
/// 1 / step) is the one TraceCounters::hintSlot names: its k = floor(T / step) picks the slot of
/// the tile's ray-hint table, so DualMeshMedium tests the primitive that claimed the previous
/// ray's k-th sample. Without a table (GPU threads, single queries) it does nothing.
struct RayHintSlot
{
  TraceCounters& counters;
  AMRDM_HD RayHintSlot(TraceCounters& c, float T, float invStep)
    : counters(c)
  {
    const float k = std::floor(T * invStep);
    if (c.rayHints && k >= -1e18f && k <= 1e18f) // false for NaN: no slot rather than UB
    {
      c.hintSlot = std::uint32_t(static_cast<long long>(k)) & (kRayHintSlots - 1);
    }
  }
  AMRDM_HD ~RayHintSlot() { this->counters.hintSlot = ~0u; }
  RayHintSlot(const RayHintSlot&) = delete;
  RayHintSlot& operator=(const RayHintSlot&) = delete;
};

/// Walks the macrocell segments of `ray` over [0, tmax] ∩ grid bounds and calls
/// visit(t, length) for every sample, front to back, until visit returns false.
/// skip(segment) true leaves a segment without samples (no data, or transparent).
/// Uniform step (samplesPerCell <= 0): one lattice T = (k + jitter) * step measured from the
/// camera ray's true origin (T = t + ray.tCamera), so neither skipped segments nor a moved
/// origin (clipping planes, a data-parallel region's box) shift the samples: sample k belongs to
/// the segment with T0 <= T_k < T1, and the regions' shared cut is the same float on both sides;
/// each sample weighs `step`. Level-adaptive step (samplesPerCell > 0): each segment [t0, t1]
/// not skipped is cut into strata of h = min(span, max(step, cellWidth / samplesPerCell)) (the
/// last one shorter), one sample at `jitter` inside each, weighing its stratum's length (no cell
/// width: +inf, one stratum per segment). step <= 0: no samples.
template<typename Skip, typename Visit>
AMRDM_HD void marchLattice(const MajorantGridView& grid,
  const Ray& ray,
  float tmax,
  float step,
  float samplesPerCell,
  float jitter,
  Skip&& skip,
  Visit&& visit)
{
  if (!(step > 0.0f))
  {
    return;
  }
  DdaMajorantIterator it(grid, ray, 0.0f, tmax);
  long long k = 0; // uniform step: index of the next lattice sample
  bool first = true;
  bool going = true;
  // The previous segment was walked: k is already the first index with T_k >= this segment's
  // T0 (the walk stopped at T_k >= its T1, the same float), so the search below is skipped.
  bool contiguous = false;
  MajorantSegment seg;
  while (going && it.next(seg))
  {
    if (skip(seg))
    {
      contiguous = false;
      continue;
    }
    if (samplesPerCell > 0.0f)
    {
      const float width = grid.cellWidth ? grid.cellWidth[seg.cell] : kInfinity;
      const float span = seg.t1 - seg.t0;
      const float h = glm::min(span, glm::max(step, width / samplesPerCell));
      for (int j = 0; going && float(j) * h < span; ++j)
      {
        const float s0 = float(j) * h;
        const float length = glm::min(h, span - s0);
        going = visit(seg.t0 + s0 + jitter * length, length);
      }
      continue;
    }
    const float T1 = seg.t1 + ray.tCamera;
    if (!contiguous)
    {
      const float T0 = seg.t0 + ray.tCamera;
      long long k0 = (long long)(std::ceil(T0 / step - jitter));
      if ((float(k0) + jitter) * step < T0)
      {
        ++k0;
      }
      else if ((float(k0 - 1) + jitter) * step >= T0)
      {
        --k0;
      }
      k = first || k0 > k ? k0 : k;
      first = false;
      contiguous = true;
    }
    for (; going; ++k)
    {
      const float T = (float(k) + jitter) * step;
      if (!(T < T1))
      {
        break;
      }
      going = visit(T - ray.tCamera, step);
    }
  }
}

} // namespace amrdm
