// Shape functions of the stitching elements (VTK corner order and VTK parametric coordinates),
// their parametric derivatives, and the element-local frame the element tests work in.
// Host/device code; no VTK. Used by Elements.h.
#pragma once

#include "core/HostDevice.h"

namespace amrdm
{

/// Element corners moved into a local frame: x = (corner - corner0) / largest bounding-box extent,
/// so every element spans [-1, 1]^3 at most whatever its physical size and position. Tolerances
/// in Elements.h are relative to the element through this frame. Subtracting corner 0 (a float
/// close to the other corners) is exact, so a 1e6 offset costs no precision beyond that of the
/// input floats themselves.
template<int N>
struct LocalElement
{
  glm::vec3 x[N]; ///< corners in the local frame
  float f[N];     ///< corner values
  glm::vec3 q;    ///< the query point in the local frame
};

/// Fills `e` from corners `v` (x, y, z, value) and point p. False when the element has no
/// extent (all corners equal) or non-finite coordinates.
template<int N>
AMRDM_HD bool makeLocalElement(const glm::vec4* v, const glm::vec3& p, LocalElement<N>& e)
{
  const glm::vec3 origin(v[0]);
  glm::vec3 lo(0.0f), hi(0.0f);
  for (int i = 0; i < N; ++i)
  {
    e.x[i] = glm::vec3(v[i]) - origin;
    e.f[i] = v[i].w;
    lo = glm::min(lo, e.x[i]);
    hi = glm::max(hi, e.x[i]);
  }
  const glm::vec3 ext = hi - lo;
  const float extent = glm::max(ext.x, glm::max(ext.y, ext.z));
  // Also false for NaN (comparison fails) and for infinite extents.
  if (!(extent > 0.0f) || !(extent < 3.0e38f))
  {
    return false;
  }
  const float inv = 1.0f / extent;
  for (int i = 0; i < N; ++i)
  {
    e.x[i] *= inv;
  }
  e.q = (p - origin) * inv;
  return true;
}

/// Σ w_i y_i for any corner quantity y (positions or values).
template<int N, class T>
AMRDM_HD T interpolateCorners(const float* w, const T* y)
{
  T sum = w[0] * y[0];
  for (int i = 1; i < N; ++i)
  {
    sum += w[i] * y[i];
  }
  return sum;
}

AMRDM_HD glm::vec3 clamp01(const glm::vec3& pc)
{
  return glm::clamp(pc, glm::vec3(0.0f), glm::vec3(1.0f));
}

/// The bilinear quad of a layer of corners (r, s) = (0,0), (1,0), (1,1), (0,1), times the
/// layer's weight f along t, into w[0..3]: the hex's bottom (f = 1 - t) and top (f = t) and the
/// pyramid's base.
AMRDM_HD void quadLayerWeights(float r, float s, float f, float* w)
{
  const float rm = 1.0f - r, sm = 1.0f - s;
  w[0] = rm * sm * f;
  w[1] = r * sm * f;
  w[2] = r * s * f;
  w[3] = rm * s * f;
}

/// The derivatives (d/dr, d/ds, d/dt) of quadLayerWeights into d[0..3]; df = df/dt (-1 or 1).
AMRDM_HD void quadLayerDerivatives(float r, float s, float f, float df, glm::vec3* d)
{
  const float rm = 1.0f - r, sm = 1.0f - s;
  d[0] = glm::vec3(-sm * f, -rm * f, df * rm * sm);
  d[1] = glm::vec3(sm * f, -r * f, df * r * sm);
  d[2] = glm::vec3(s * f, r * f, df * r * s);
  d[3] = glm::vec3(-s * f, rm * f, df * rm * s);
}

/// Trilinear hexahedron. Corners 0-3 bottom (t = 0), 4-7 top (t = 1); corner i at
/// (r, s) = (0,0), (1,0), (1,1), (0,1) for i % 4 = 0..3.
struct HexShape
{
  static constexpr int kCorners = 8;

  AMRDM_HD static glm::vec3 center() { return glm::vec3(0.5f); }

  AMRDM_HD static void weights(const glm::vec3& pc, float* w)
  {
    quadLayerWeights(pc.x, pc.y, 1.0f - pc.z, w);
    quadLayerWeights(pc.x, pc.y, pc.z, w + 4);
  }

  /// d[i] = (dN_i/dr, dN_i/ds, dN_i/dt).
  AMRDM_HD static void derivatives(const glm::vec3& pc, glm::vec3* d)
  {
    quadLayerDerivatives(pc.x, pc.y, 1.0f - pc.z, -1.0f, d);
    quadLayerDerivatives(pc.x, pc.y, pc.z, 1.0f, d + 4);
  }

  AMRDM_HD static bool inReference(const glm::vec3& pc, float tol)
  {
    return pc.x >= -tol && pc.y >= -tol && pc.z >= -tol && pc.x <= 1.0f + tol &&
           pc.y <= 1.0f + tol && pc.z <= 1.0f + tol;
  }

  AMRDM_HD static glm::vec3 clampToReference(const glm::vec3& pc) { return clamp01(pc); }
};

/// Wedge (VTK_WEDGE): triangle 0,1,2 at t = 0 and 3,4,5 at t = 1 (corner i + 3 above corner i);
/// linear triangle in (r, s) with corners (0,0), (1,0), (0,1), times linear in t.
struct WedgeShape
{
  static constexpr int kCorners = 6;

  AMRDM_HD static glm::vec3 center() { return glm::vec3(1.0f / 3.0f, 1.0f / 3.0f, 0.5f); }

  AMRDM_HD static void weights(const glm::vec3& pc, float* w)
  {
    const float r = pc.x, s = pc.y, t = pc.z;
    const float u = 1.0f - r - s, tm = 1.0f - t;
    w[0] = u * tm;
    w[1] = r * tm;
    w[2] = s * tm;
    w[3] = u * t;
    w[4] = r * t;
    w[5] = s * t;
  }

  AMRDM_HD static void derivatives(const glm::vec3& pc, glm::vec3* d)
  {
    const float r = pc.x, s = pc.y, t = pc.z;
    const float u = 1.0f - r - s, tm = 1.0f - t;
    d[0] = glm::vec3(-tm, -tm, -u);
    d[1] = glm::vec3(tm, 0.0f, -r);
    d[2] = glm::vec3(0.0f, tm, -s);
    d[3] = glm::vec3(-t, -t, u);
    d[4] = glm::vec3(t, 0.0f, r);
    d[5] = glm::vec3(0.0f, t, s);
  }

  AMRDM_HD static bool inReference(const glm::vec3& pc, float tol)
  {
    return pc.x >= -tol && pc.y >= -tol && pc.x + pc.y <= 1.0f + tol && pc.z >= -tol &&
           pc.z <= 1.0f + tol;
  }

  /// Nearest-enough point of the reference wedge: (r, s) into the triangle, t into [0, 1].
  AMRDM_HD static glm::vec3 clampToReference(const glm::vec3& pc)
  {
    glm::vec3 c = clamp01(pc);
    const float sum = c.x + c.y;
    if (sum > 1.0f)
    {
      c.x /= sum;
      c.y /= sum;
    }
    return c;
  }
};

/// Pyramid (VTK_PYRAMID): quad base 0-3 at t = 0 (bilinear in r, s like the hex bottom), apex 4
/// at t = 1; x = (1 - t) * base(r, s) + t * apex.
struct PyramidShape
{
  static constexpr int kCorners = 5;

  /// The centroid of the reference pyramid lies at a quarter of its height.
  AMRDM_HD static glm::vec3 center() { return glm::vec3(0.5f, 0.5f, 0.25f); }

  AMRDM_HD static void weights(const glm::vec3& pc, float* w)
  {
    quadLayerWeights(pc.x, pc.y, 1.0f - pc.z, w);
    w[4] = pc.z;
  }

  AMRDM_HD static void derivatives(const glm::vec3& pc, glm::vec3* d)
  {
    quadLayerDerivatives(pc.x, pc.y, 1.0f - pc.z, -1.0f, d);
    d[4] = glm::vec3(0.0f, 0.0f, 1.0f);
  }

  AMRDM_HD static bool inReference(const glm::vec3& pc, float tol)
  {
    return HexShape::inReference(pc, tol);
  }

  AMRDM_HD static glm::vec3 clampToReference(const glm::vec3& pc) { return clamp01(pc); }
};

} // namespace amrdm
