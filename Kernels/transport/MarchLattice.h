// The ray marcher's sample lattice, walked once for every integrator that samples along camera
// rays at discrete points (transport/RayMarcher.h: emission-absorption compositing;
// transport/BlendModes.h: the projection blend modes). Host/device code.
#pragma once

#include "accel/MajorantIterator.h"

#include <cmath>

namespace amrdm
{

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
  MajorantSegment seg;
  while (going && it.next(seg))
  {
    if (skip(seg))
    {
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
    const float T0 = seg.t0 + ray.tCamera;
    const float T1 = seg.t1 + ray.tCamera;
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

/// Walks the non-skipped macrocell segments of `ray` over [0, tmax] ∩ grid bounds in intervals
/// of equal majorant optical depth and calls visit(t, length) once per interval, front to back,
/// until visit returns false: each interval [s, e) holds at most `tau` of the majorant's optical
/// depth (sum of sigmaMaj x length over the segments it covers), is at least `minStep` long
/// (even where that holds more) and at most `maxStep`, and ends where a skipped segment or the
/// walk begins; one sample at s + jitter (e - s), weighing e - s. Where the majorant is
/// sigma_max everywhere this is the uniform step max(minStep, tau / sigma_max); where the
/// medium is thinner the intervals grow, and an interval that reaches denser macrocells closes
/// as soon as it holds `tau` there. Each interval's sample is uniform over it (jitter uniform),
/// so each one's sum is an unbiased estimate of its integral. Not anchored at the camera: a
/// data-parallel region's piece of a ray starts a new interval at the region's face (the ray
/// marcher keeps marchLattice() there). minStep <= 0 or tau <= 0: no samples.
template<typename Skip, typename Visit>
AMRDM_HD void marchOpticalDepth(const MajorantGridView& grid,
  const Ray& ray,
  float tmax,
  float minStep,
  float maxStep,
  float tau,
  float jitter,
  Skip&& skip,
  Visit&& visit)
{
  if (!(minStep > 0.0f) || !(tau > 0.0f))
  {
    return;
  }
  maxStep = glm::max(maxStep, minStep);
  DdaMajorantIterator it(grid, ray, 0.0f, tmax);
  bool open = false;  // an interval [s, ...) is open
  float s = 0.0f;     // its start
  float depth = 0.0f; // majorant optical depth it holds up to the start of this segment
  float end = 0.0f;   // the end of the last segment walked (not skipped)
  bool going = true;
  MajorantSegment seg;
  while (going && it.next(seg))
  {
    if (skip(seg))
    {
      if (open)
      {
        going = visit(s + jitter * (end - s), end - s);
        open = false;
      }
      continue;
    }
    if (!open)
    {
      open = true;
      s = seg.t0;
      depth = 0.0f;
    }
    float t = seg.t0; // [t, seg.t1) is left in this segment
    while (going)
    {
      // Where the interval would hold tau: t + (tau - depth) / sigma, within [s + minStep,
      // s + maxStep].
      float e = t + (tau - depth) / seg.sigmaMaj;
      e = glm::max(glm::min(e, s + maxStep), s + minStep);
      if (!(e < seg.t1) || !(e > s))
      {
        depth += seg.sigmaMaj * (seg.t1 - t);
        break;
      }
      going = visit(s + jitter * (e - s), e - s);
      s = e;
      t = e;
      depth = 0.0f;
    }
    end = seg.t1;
  }
  if (going && open && end > s)
  {
    visit(s + jitter * (end - s), end - s);
  }
}

} // namespace amrdm
