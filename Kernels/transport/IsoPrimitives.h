// The exact isosurface crossings of one primitive along a ray (transport/Isosurface.h walks
// the primitives): a gridlet's dual cells by a DDA, each perfect cube's trilinear interpolant a
// cubic in t (transport/IsoRoots.h); a stitching element's own interpolant bracketed along the
// part of the chord it claims. Host/device code.
#pragma once

#include "sampling/Media.h"
#include "transport/ElementChord.h"
#include "transport/IsoRoots.h"

namespace amrdm
{

/// Sub-intervals of an element's chord searched for sign changes.
constexpr int kIsoElementIntervals = 8;

/// The nearest crossing found so far.
struct IsoHit
{
  float t = kInfinity;        ///< ray parameter (world units along the unit direction)
  int index = -1;             ///< which value of the list
  glm::vec3 gradient{ 0.0f }; ///< world-space gradient of the interpolant at the hit
  float skip = 0.0f;          ///< the next search starts at t + skip (past this crossing)
  AMRDM_HD bool hit() const { return this->index >= 0; }
};

/// One exact search of the dual mesh along a ray: the line og + t dg in grid coordinates, the
/// values (numIso of them), the nearest crossing found so far (updated) and the work counters.
/// Isosurface.h's isoBvh hands it to isoGridlet and isoElement.
struct IsoRay
{
  const DualMeshMedium& medium;
  glm::vec3 og, dg;
  const float* iso;
  int numIso;
  IsoHit& best;
  TraceCounters& counters;
};

/// True when [range.x, range.y] can hold one of the values.
AMRDM_HD bool rangeHoldsIso(const glm::vec2& range, const float* iso, int numIso)
{
  for (int k = 0; k < numIso; ++k)
  {
    if (range.x <= iso[k] && iso[k] <= range.y)
    {
      return true;
    }
  }
  return false;
}

/// [t0, t1] clipped to the closed box [lo, hi] of the line o + t d; false when empty. A line
/// parallel to an axis (d[a] == 0) is inside the slab when lo[a] <= o[a] <= hi[a], its faces
/// included: a ray lying exactly in the face plane shared by two boxes (a parallel camera along
/// an axis puts rows of rays in the planes of cell centres) belongs to both, not to neither
/// ((lo - o) / 0 would be NaN there, and fmin / fmax would turn it into an empty slab).
AMRDM_HD bool clipLineToBox(const glm::vec3& o,
  const glm::vec3& d,
  const glm::vec3& lo,
  const glm::vec3& hi,
  float& t0,
  float& t1)
{
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] == 0.0f)
    {
      if (o[a] < lo[a] || o[a] > hi[a])
      {
        return false;
      }
      continue;
    }
    const float inv = 1.0f / d[a];
    const float ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    t0 = fmaxf(t0, fminf(ta, tb));
    t1 = fminf(t1, fmaxf(ta, tb));
  }
  return t0 <= t1;
}

/// FLT_EPSILON (host and device).
constexpr float kIsoFloatEpsilon = 1.1920929e-7f;

/// Float rounding of a gridlet-local coordinate of magnitude `mag` (cells), times a safety
/// factor: how far two evaluations of one face point may disagree about where it is. Capped
/// well below the skip past a hit (1e-3 cell, IsoHit::skip) so that a continued search never
/// finds the crossing it continues from.
AMRDM_HD float isoFaceSlack(float mag)
{
  return fminf(16.0f * kIsoFloatEpsilon * (mag + 1.0f), 1e-4f);
}

/// Isosurface crossings of gridlet `index` along the grid-space line r.og + t r.dg, t in
/// [t0, min(t1, r.best.t)): the first one, if nearer than r.best, replaces it.
///
/// Each dual cell's cubic is searched on its chord [ta, tc] widened by isoFaceSlack on both
/// sides (the trilinear form extended a hair past the cell, never before t0 nor past t1): the
/// two cells (or primitives) sharing a face evaluate the face point separately, and where the
/// surface passes within rounding of the face their values can both land on the far side of
/// it, so that neither side alone sees the sign change (a missed first crossing: the search
/// returned a later one). A root in the slack is reported where the widened cubic has it:
/// nearer the interpolant's surface than the face itself.
AMRDM_HD void isoGridlet(const IsoRay& r, std::uint32_t index, float t0, float t1)
{
  const GridletHeader& g = r.medium.mesh.gridlets[index];
  const float w = r.medium.mesh.levelWidth[g.level];
  // Gridlet-local cell coordinates along the ray: L0 + t Ld.
  const glm::vec3 L0 = r.og / w - r.medium.mesh.gridletOrigin - glm::vec3(g.lower);
  const glm::vec3 Ld = r.dg / w;
  t1 = fminf(t1, r.best.t);
  const float tMin = t0, tMax = t1; // the caller's window, before clipping to the gridlet
  if (!clipLineToBox(L0, Ld, glm::vec3(0.0f), glm::vec3(g.dims), t0, t1))
  {
    return;
  }
  glm::ivec3 cell, step;
  glm::vec3 next, delta;
  const glm::vec3 entry = L0 + t0 * Ld;
  for (int a = 0; a < 3; ++a)
  {
    cell[a] = glm::clamp(int(std::floor(entry[a])), 0, g.dims[a] - 1);
    step[a] = Ld[a] > 0.0f ? 1 : (Ld[a] < 0.0f ? -1 : 0);
    delta[a] = step[a] != 0 ? 1.0f / std::fabs(Ld[a]) : kInfinity;
    next[a] = step[a] > 0   ? t0 + (float(cell[a] + 1) - entry[a]) / Ld[a]
              : step[a] < 0 ? t0 + (float(cell[a]) - entry[a]) / Ld[a]
                            : kInfinity;
  }
  const float maxRate = glm::max(std::fabs(Ld.x), glm::max(std::fabs(Ld.y), std::fabs(Ld.z)));
  // The slack in t: the rounding of L0 + t Ld, whose terms reach |L0| and |t1 Ld| cells.
  const glm::vec3 mag = glm::abs(L0) + std::fabs(t1) * glm::abs(Ld);
  const float slack = isoFaceSlack(glm::max(mag.x, glm::max(mag.y, mag.z))) / maxRate;
  const int nx = g.dims.x + 1, ny = g.dims.y + 1;
  float ta = t0;
  for (;;)
  {
    const int axis = next.x < next.y ? (next.x < next.z ? 0 : 2) : (next.y < next.z ? 1 : 2);
    const float tc = fminf(next[axis], t1);
    ++r.counters.steps;
    const float* s = r.medium.mesh.gridletScalars + g.begin + (cell.z * ny + cell.y) * nx + cell.x;
    const float v[8] = {
      s[0], s[1], s[nx], s[nx + 1], s[nx * ny], s[nx * ny + 1], s[nx * ny + nx], s[nx * ny + nx + 1]
    };
    bool perfect = true;
    float lo = v[0], hi = v[0];
    for (int i = 0; i < 8; ++i)
    {
      perfect = perfect && v[i] == v[i]; // NaN: not a perfect cube of this gridlet
      lo = fminf(lo, v[i]);
      hi = fmaxf(hi, v[i]);
    }
    bool found = false;
    // The cell's chord widened by the slack (see above), inside the caller's window.
    const float wa = fmaxf(ta - slack, tMin), wb = fminf(tc + slack, tMax);
    if (perfect && wb > wa)
    {
      const glm::vec3 p = L0 + wa * Ld - glm::vec3(cell);
      for (int k = 0; k < r.numIso; ++k)
      {
        // The corners bound the interpolant in the cell; the slack lets it stray by
        // |grad| x slack beyond them.
        const float reach = (hi - lo) * 3.0f * slack * maxRate;
        if (!(lo - reach <= r.iso[k] && r.iso[k] <= hi + reach))
        {
          continue;
        }
        float c[4];
        trilinearCubic(v, p, Ld, r.iso[k], c);
        float root = 0.0f;
        if (firstCubicRoot(c, wb - wa, root) && wa + root < r.best.t)
        {
          const glm::vec3 f = glm::clamp(p + root * Ld, glm::vec3(0.0f), glm::vec3(1.0f));
          r.best.t = wa + root; // in the slack: within a rounding's width of the face
          r.best.index = k;
          r.best.gradient = trilinearGradient(v, f) * r.medium.invSpacing / w;
          r.best.skip = 1e-3f / maxRate;
          found = true;
        }
      }
    }
    if (found || !(next[axis] < t1) || step[axis] == 0)
    {
      return; // cells come in ray order: the first cell with a crossing holds the nearest
    }
    ta = next[axis];
    cell[axis] += step[axis];
    if (cell[axis] < 0 || cell[axis] >= g.dims[axis])
    {
      return;
    }
    next[axis] += delta[axis];
  }
}

/// Isosurface crossings of stitching element `index` of kind `kind` along r (see
/// isoGridlet), with the element's own interpolant.
AMRDM_HD void isoElement(const IsoRay& r, int kind, std::uint32_t index, float t0, float t1)
{
  glm::vec4 v[kMaxElementCorners];
  glm::ivec3 anchor2;
  const int n = gatherElement(r.medium.mesh, kind, index, v, anchor2);
  const glm::vec3 q0 = r.og - 0.5f * glm::vec3(anchor2); // the line in the element's frame
  glm::vec3 lo(v[0]), hi(v[0]);
  for (int i = 1; i < n; ++i)
  {
    lo = glm::min(lo, glm::vec3(v[i]));
    hi = glm::max(hi, glm::vec3(v[i]));
  }
  const glm::vec3 pad = (hi - lo) * kElementBoxPad;
  t1 = fminf(t1, r.best.t);
  if (!clipLineToBox(q0, r.dg, lo - pad, hi + pad, t0, t1))
  {
    return;
  }
  auto value = [&](float t, float& f)
  { return sampleElementOfKind(kind, v, q0 + t * r.dg, r.medium.elementTest, f); };
  // The claimed pieces of the chord (transport/ElementChord.h), in ray order; the first with a
  // bracketed sign change holds the nearest crossing.
  float pieceLo[kElementChordPieces], pieceHi[kElementChordPieces];
  const int pieces = elementChord(
    kind,
    v,
    q0,
    r.dg,
    t0,
    t1,
    [&](float t)
    {
      float f = 0.0f;
      return value(t, f);
    },
    pieceLo,
    pieceHi);
  // Past a crossing: a thousandth of the element's size along the ray (not of the piece,
  // which may be a sliver).
  const glm::vec3 ext = hi - lo, rate = glm::abs(r.dg);
  const float skip =
    1e-3f * fmaxf(ext.x, fmaxf(ext.y, ext.z)) / fmaxf(rate.x, fmaxf(rate.y, fmaxf(rate.z, 1e-30f)));
  bool found = false;
  for (int piece = 0; piece < pieces && !found; ++piece)
  {
    const float e0 = pieceLo[piece], len = pieceHi[piece] - e0;
    float ts[kIsoElementIntervals + 1], fs[kIsoElementIntervals + 1];
    bool ok[kIsoElementIntervals + 1];
    for (int i = 0; i <= kIsoElementIntervals; ++i)
    {
      ts[i] = i == kIsoElementIntervals ? pieceHi[piece]
                                        : e0 + len * float(i) / float(kIsoElementIntervals);
      ok[i] = value(ts[i], fs[i]);
    }
    for (int k = 0; k < r.numIso; ++k)
    {
      auto shifted = [&](float t, float& f)
      {
        const bool in = value(t, f);
        f -= r.iso[k];
        return in;
      };
      for (int i = 0; i < kIsoElementIntervals && ts[i] < r.best.t; ++i)
      {
        if (!ok[i] || !ok[i + 1])
        {
          continue;
        }
        const float fa = fs[i] - r.iso[k], fb = fs[i + 1] - r.iso[k];
        float root;
        if (fa == 0.0f)
        {
          root = ts[i];
        }
        else if (fb != 0.0f && (fa > 0.0f) == (fb > 0.0f))
        {
          continue;
        }
        else
        {
          root = fb == 0.0f ? ts[i + 1]
                            : refineRoot(shifted, ts[i], ts[i + 1], fa, fb, len * kNewtonConverged);
        }
        if (root < r.best.t)
        {
          r.best.t = root;
          r.best.index = k;
          r.best.skip = skip;
          found = true;
        }
        break;
      }
    }
  }
  if (!found)
  {
    return;
  }
  // Gradient: central differences of the field (the element's interpolant, or its neighbour's
  // across a face: C0), one-sided where one side has no data.
  const glm::vec3 g = r.og + r.best.t * r.dg;
  float centre = 0.0f;
  value(r.best.t, centre);
  glm::vec3 grad(0.0f);
  for (int a = 0; a < 3; ++a)
  {
    glm::vec3 h(0.0f);
    h[a] = 1e-2f * fmaxf(hi[a] - lo[a], 1e-30f);
    float vp = centre, vm = centre;
    const bool hp = sampleField(r.medium.mesh, g + h, r.medium.elementTest, vp);
    const bool hm = sampleField(r.medium.mesh, g - h, r.medium.elementTest, vm);
    const float span = (hp ? h[a] : 0.0f) + (hm ? h[a] : 0.0f);
    grad[a] = span > 0.0f ? ((hp ? vp : centre) - (hm ? vm : centre)) / span : 0.0f;
  }
  r.best.gradient = grad * r.medium.invSpacing;
}

} // namespace amrdm
