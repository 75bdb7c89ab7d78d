// Exact ray-isosurface intersection with the dual-mesh interpolant (blend mode Isosurface,
// transport/BlendModes.h). The ray is cut into runs of macrocells whose value range
// (MajorantGridView::range) can hold an isosurface value; the rest is skipped unvisited. Inside
// a run, a BVH ray query visits the primitives the ray crosses, nearest box first, pruned by the
// best hit so far. In a gridlet, a DDA walks the dual cells the ray crosses; in each perfect cube
// whose corners straddle a value, the trilinear interpolant along the ray is a cubic in t whose
// first root is found exactly (transport/IsoRoots.h: split at the derivative's roots, Illinois
// refinement to kNewtonConverged of the chord). In a stitching element the element's own
// interpolant (sampleElementOfKind, Newton inversion where it has no closed form) is sampled at
// kIsoElementIntervals sub-intervals of each piece of the chord it claims (exact pieces between
// the line's crossings of its faces, transport/ElementChord.h), and a bracketed sign change is
// refined the same way. A crossing on a face between two cells or primitives is found on
// either side: each cell's cubic is searched a rounding's width past its faces (isoFaceSlack). The
// gradient for shading is analytic in gridlets (derivative of the trilinear form) and a central
// difference of the field (the element's interpolant and its neighbours') at a hundredth of the
// element's size in elements. Other media (analytic test media) bracket sign changes at the
// ray-marching step instead. Host/device code.
#pragma once

#include "accel/MajorantIterator.h"
#include "transport/IsoPrimitives.h"

namespace amrdm
{

/// The nearest crossing of the primitives along r.og + t r.dg, t in [t0, t1], through a BVH ray
/// query (nearest child first, pruned by the best hit).
AMRDM_HD void isoBvh(const IsoRay& r, float t0, float t1)
{
  const BvhView& bvh = r.medium.mesh.bvh;
  if (bvh.numNodes == 0)
  {
    return;
  }
  auto enter = [&](std::uint32_t node, float& tn) -> bool
  {
    if (bvh.nodeVisible && !bvh.nodeVisible[node])
    {
      return false;
    }
    float a = t0, b = fminf(t1, r.best.t);
    const bool in = clipLineToBox(r.og, r.dg, bvh.nodes[node].lo, bvh.nodes[node].hi, a, b);
    tn = a;
    return in;
  };
  std::uint32_t stack[kBvhMaxDepth];
  int top = 0;
  float tn = 0.0f;
  if (!enter(0, tn))
  {
    return;
  }
  std::uint32_t node = 0;
  for (;;)
  {
    const BvhNode& n = bvh.nodes[node];
    bool descended = false;
    if (n.count == 0)
    {
      float ta = 0.0f, tb = 0.0f;
      const bool ha = enter(n.first, ta), hb = enter(n.first + 1, tb);
      if (ha && hb)
      {
        stack[top++] = ta <= tb ? n.first + 1 : n.first;
        node = ta <= tb ? n.first : n.first + 1;
        descended = true;
      }
      else if (ha || hb)
      {
        node = ha ? n.first : n.first + 1;
        descended = true;
      }
    }
    else
    {
      for (std::uint32_t i = 0; i < n.count; ++i)
      {
        if (bvh.slotVisible && !bvh.slotVisible[n.first + i])
        {
          continue;
        }
        const std::uint32_t ref = bvh.prims[n.first + i];
        const std::uint32_t type = primType(ref);
        if (r.medium.countPrimitiveTests)
        {
          ++r.counters.primitiveTests;
        }
        if (type == PrimGridlet)
        {
          isoGridlet(r, primIndex(ref), t0, t1);
        }
        else if (isElementPrimType(type))
        {
          isoElement(r, primElementKind(type), primIndex(ref), t0, t1);
        }
      }
    }
    if (descended)
    {
      continue;
    }
    // Pop the next subtree that can still hold a nearer crossing.
    bool popped = false;
    while (top > 0 && !popped)
    {
      node = stack[--top];
      popped = enter(node, tn);
    }
    if (!popped)
    {
      return;
    }
  }
}

/// The nearest isosurface crossing of the dual-mesh field along `ray` in [tFrom, tTo]: runs of
/// macrocells whose value range can hold a value, each searched by isoBvh until one has a hit.
/// `step` is unused (the search is exact).
AMRDM_HD IsoHit findIsoHit(const DualMeshMedium& medium,
  const MajorantGridView& grid,
  const Ray& ray,
  float tFrom,
  float tTo,
  const float* iso,
  int numIso,
  float /*step*/,
  TraceCounters& counters)
{
  IsoHit best;
  const IsoRay r{
    medium, medium.toGrid(ray.o), ray.d * medium.invSpacing, iso, numIso, best, counters
  };
  DdaMajorantIterator it(grid, ray, tFrom, tTo);
  MajorantSegment seg;
  bool open = false;
  float a = 0.0f, b = 0.0f;
  while (it.next(seg))
  {
    if (!grid.range || rangeHoldsIso(grid.range[seg.cell], iso, numIso))
    {
      a = open ? a : seg.t0;
      b = seg.t1;
      open = true;
      continue;
    }
    if (open)
    {
      isoBvh(r, a, b);
      open = false;
      if (best.hit())
      {
        return best;
      }
    }
  }
  if (open)
  {
    isoBvh(r, a, b);
  }
  return best;
}

/// Any other medium (analytic test media): sign changes bracketed at `step` over the ray's part
/// inside the grid bounds, refined like the exact search; gradient by central differences.
template<typename Medium>
AMRDM_HD IsoHit findIsoHit(const Medium& medium,
  const MajorantGridView& grid,
  const Ray& ray,
  float tFrom,
  float tTo,
  const float* iso,
  int numIso,
  float step,
  TraceCounters& counters)
{
  IsoHit best;
  float t0 = tFrom, t1 = tTo;
  if (grid.res.x <= 0 || !clipRayToBox(ray, grid.lo, grid.hi, t0, t1) || !(step > 0.0f))
  {
    return best;
  }
  float prevT = t0, prevV = 0.0f;
  bool prevOk = medium.value(ray.at(t0), prevV, counters);
  for (float t = t0; t < t1 && !best.hit();)
  {
    const float tNext = fminf(t + step, t1);
    if (!(tNext > t))
    {
      break; // the step vanished against t (float)
    }
    t = tNext;
    float vt = 0.0f;
    const bool ok = medium.value(ray.at(t), vt, counters);
    for (int k = 0; ok && prevOk && k < numIso; ++k)
    {
      const float fa = prevV - iso[k], fb = vt - iso[k];
      if (fa != 0.0f && fb != 0.0f && (fa > 0.0f) == (fb > 0.0f))
      {
        continue;
      }
      auto f = [&](float s, float& out)
      {
        const bool in = medium.value(ray.at(s), out, counters);
        out -= iso[k];
        return in;
      };
      const float root = fa == 0.0f   ? prevT
                         : fb == 0.0f ? t
                                      : refineRoot(f, prevT, t, fa, fb, step * kNewtonConverged);
      if (root < best.t)
      {
        best.t = root;
        best.index = k;
        best.skip = 1e-3f * step;
      }
    }
    prevT = t;
    prevV = vt;
    prevOk = ok;
  }
  if (best.hit())
  {
    const glm::vec3 p = ray.at(best.t);
    const float h = 1e-2f * step;
    for (int a = 0; a < 3; ++a)
    {
      glm::vec3 e(0.0f);
      e[a] = h;
      float vp = 0.0f, vm = 0.0f;
      if (medium.value(p + e, vp, counters) && medium.value(p - e, vm, counters))
      {
        best.gradient[a] = (vp - vm) / (2.0f * h);
      }
    }
  }
  return best;
}

} // namespace amrdm
