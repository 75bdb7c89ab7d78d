// Roots along a ray for the exact isosurfaces (transport/Isosurface.h): the first root of a cubic
// on an interval (a trilinear dual cell along a ray), the bracketed refinement shared with the
// stitching elements, and the trilinear cell's cubic and gradient. Host/device code.
#pragma once

#include "core/HostDevice.h"
#include "core/Ray.h"
#include "core/Tolerances.h"

#include <cmath>

namespace amrdm
{

/// Refines a root of f bracketed by [a, b] (fa = f(a), fb = f(b) of opposite signs, neither 0)
/// by the Illinois variant of regula falsi, with a bisection step whenever an update fails to
/// halve the bracket, until the bracket is below `tol`. Returns the secant point of the last
/// bracket (exact for a linear f). f(t, value) returns false where it has no value (an element's
/// outside): the refinement then stops with the bracket it has.
template<typename F>
AMRDM_HD float refineRoot(F&& f, float a, float b, float fa, float fb, float tol)
{
  int side = 0;
  for (int i = 0; i < 64 && b - a > tol; ++i)
  {
    const float width = b - a;
    float m = (fa * b - fb * a) / (fa - fb);
    if (!(m > a && m < b))
    {
      m = 0.5f * (a + b);
    }
    float fm = 0.0f;
    if (!f(m, fm))
    {
      break;
    }
    if (fm == 0.0f)
    {
      return m;
    }
    if ((fm > 0.0f) == (fb > 0.0f))
    {
      b = m;
      fb = fm;
      fa = side == -1 ? 0.5f * fa : fa;
      side = -1;
    }
    else
    {
      a = m;
      fa = fm;
      fb = side == 1 ? 0.5f * fb : fb;
      side = 1;
    }
    if (b - a > 0.5f * width)
    {
      // Regula falsi stuck on one side: bisect once.
      const float h = 0.5f * (a + b);
      float fh = 0.0f;
      if (!f(h, fh))
      {
        break;
      }
      if (fh == 0.0f)
      {
        return h;
      }
      if ((fh > 0.0f) == (fb > 0.0f))
      {
        b = h;
        fb = fh;
      }
      else
      {
        a = h;
        fa = fh;
      }
      side = 0;
    }
  }
  const float m = (fa * b - fb * a) / (fa - fb);
  return m >= a && m <= b ? m : 0.5f * (a + b);
}

/// c[0] + c[1] s + c[2] s^2 + c[3] s^3.
AMRDM_HD float evalCubic(const float* c, float s)
{
  return ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
}

/// The first root of the cubic c on [0, len], if any: the derivative's roots split [0, len] into
/// monotone pieces, each piece with a sign change holds exactly one root, refined to len *
/// kNewtonConverged (core/Tolerances.h). A root where the cubic only touches zero (no sign
/// change, a ray grazing the surface) is not reported.
AMRDM_HD bool firstCubicRoot(const float* c, float len, float& root)
{
  float split[4];
  int n = 0;
  split[n++] = 0.0f;
  // Roots of 3 c3 s^2 + 2 c2 s + c1, in increasing order.
  const float A = 3.0f * c[3], B = 2.0f * c[2], C = c[1];
  float r0 = kInfinity, r1 = kInfinity;
  if (A == 0.0f)
  {
    r0 = B != 0.0f ? -C / B : kInfinity;
  }
  else
  {
    const float disc = B * B - 4.0f * A * C;
    if (disc > 0.0f)
    {
      const float q = -0.5f * (B + std::copysign(std::sqrt(disc), B));
      r0 = q / A;
      r1 = q != 0.0f ? C / q : kInfinity;
      if (r1 < r0)
      {
        const float s = r0;
        r0 = r1;
        r1 = s;
      }
    }
  }
  if (r0 > 0.0f && r0 < len)
  {
    split[n++] = r0;
  }
  if (r1 > 0.0f && r1 < len)
  {
    split[n++] = r1;
  }
  split[n++] = len;
  auto f = [&](float s, float& v)
  {
    v = evalCubic(c, s);
    return true;
  };
  float fa = evalCubic(c, 0.0f);
  if (fa == 0.0f)
  {
    root = 0.0f;
    return true;
  }
  for (int i = 0; i + 1 < n; ++i)
  {
    const float a = split[i], b = split[i + 1];
    const float fb = evalCubic(c, b);
    if (fb == 0.0f)
    {
      root = b;
      return true;
    }
    if ((fa > 0.0f) != (fb > 0.0f))
    {
      root = refineRoot(f, a, b, fa, fb, len * kNewtonConverged);
      return true;
    }
    fa = fb;
  }
  return false;
}

/// The cubic in s of the trilinear interpolant of corners v (x fastest: v[i + 2j + 4k] at
/// (i, j, k)) along the line p + s d (cell-fraction coordinates), minus `iso`.
AMRDM_HD void trilinearCubic(const float* v,
  const glm::vec3& p,
  const glm::vec3& d,
  float iso,
  float* c)
{
  c[0] = c[1] = c[2] = c[3] = 0.0f;
  for (int corner = 0; corner < 8; ++corner)
  {
    float a[3], b[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      const bool upper = ((corner >> axis) & 1) != 0;
      a[axis] = upper ? p[axis] : 1.0f - p[axis];
      b[axis] = upper ? d[axis] : -d[axis];
    }
    const float w = v[corner] - iso;
    c[0] += w * a[0] * a[1] * a[2];
    c[1] += w * (b[0] * a[1] * a[2] + a[0] * b[1] * a[2] + a[0] * a[1] * b[2]);
    c[2] += w * (b[0] * b[1] * a[2] + b[0] * a[1] * b[2] + a[0] * b[1] * b[2]);
    c[3] += w * b[0] * b[1] * b[2];
  }
}

/// Gradient of the trilinear interpolant of corners v (as trilinearCubic) at cell fraction f,
/// per unit of cell fraction.
AMRDM_HD glm::vec3 trilinearGradient(const float* v, const glm::vec3& f)
{
  glm::vec3 g(0.0f);
  for (int corner = 0; corner < 8; ++corner)
  {
    const int i = corner & 1, j = (corner >> 1) & 1, k = (corner >> 2) & 1;
    const float wx = i ? f.x : 1.0f - f.x, wy = j ? f.y : 1.0f - f.y, wz = k ? f.z : 1.0f - f.z;
    const float sx = i ? 1.0f : -1.0f, sy = j ? 1.0f : -1.0f, sz = k ? 1.0f : -1.0f;
    g.x += v[corner] * sx * wy * wz;
    g.y += v[corner] * wx * sy * wz;
    g.z += v[corner] * wx * wy * sz;
  }
  return g;
}

} // namespace amrdm
