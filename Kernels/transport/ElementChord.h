// The part of a line that a stitching element claims (transport/IsoPrimitives.h searches the
// element's interpolant there for isosurface crossings). The claimed region is bounded by the
// element's faces: bilinear patches and planar triangles under the Bilinear test, the faces'
// planes under PlanarFaces (mesh/ElementTest.h). The line's crossings of every one of them
// (both roots of each patch's hyperbolic paraboloid and each face's plane, VTK corner order,
// mesh/ElementList.h) cut it into pieces on each of which the element's claim does not change,
// up to its tolerances: the midpoint of each piece, tested with the element's own sample
// function, says whether the piece is claimed. No piece is too thin to be seen, unlike probes
// at a fixed spacing (a ray that nicks a thin element's edge crosses it over a sliver of its
// box chord, where it may hold the first isosurface crossing). Host/device code.
#pragma once

#include "sampling/FieldSampler.h"

namespace amrdm
{

/// Most breakpoints of one element: a hex has 6 quad faces, each with 2 patch roots and a plane.
constexpr int kElementChordBreaks = 6 * 3;
/// Most claimed pieces reported per element (a convex element has one).
constexpr int kElementChordPieces = 4;

/// Appends the line parameters t where p0 + t d crosses the plane through `centre` with normal
/// `n` (none when the line is parallel to it).
AMRDM_HD void addPlaneBreak(const glm::vec3& n,
  const glm::vec3& centre,
  const glm::vec3& p0,
  const glm::vec3& d,
  float* breaks,
  int& count)
{
  const float den = glm::dot(n, d);
  if (den != 0.0f && count < kElementChordBreaks)
  {
    const float t = glm::dot(n, centre - p0) / den;
    if (t == t)
    {
      breaks[count++] = t;
    }
  }
}

/// 2D cross product.
AMRDM_HD float cross2(const glm::vec2& a, const glm::vec2& b)
{
  return a.x * b.y - a.y * b.x;
}

/// Appends where p0 + t d crosses the bilinear patch through corners a, b, c, d (cyclic order)
/// extended to its whole hyperbolic paraboloid (up to 2 roots), and the plane PlanarFaces
/// gives that face (normal (c - a) x (d - b) through the corners' mean). The patch is solved
/// in the plane perpendicular to the line (u1, u2): A + u E + v F + u v G = 0 is a quadratic
/// in v (the inverse bilinear map of the line's trace).
AMRDM_HD void addQuadBreaks(const glm::vec3& a,
  const glm::vec3& b,
  const glm::vec3& c,
  const glm::vec3& dc,
  const glm::vec3& p0,
  const glm::vec3& d,
  const glm::vec3& u1,
  const glm::vec3& u2,
  float* breaks,
  int& count)
{
  addPlaneBreak(glm::cross(c - a, dc - b), 0.25f * (a + b + c + dc), p0, d, breaks, count);
  auto proj = [&](const glm::vec3& x)
  { return glm::vec2(glm::dot(x - p0, u1), glm::dot(x - p0, u2)); };
  const glm::vec2 A = proj(a), B = proj(b), C = proj(c), D = proj(dc);
  const glm::vec2 E = B - A, F = D - A, G = A - B + C - D, H = -A;
  const float k2 = cross2(G, F), k1 = cross2(E, F) + cross2(H, G), k0 = cross2(H, E);
  const float scale = fmaxf(fabsf(k2), fmaxf(fabsf(k1), fabsf(k0)));
  if (!(scale > 0.0f))
  {
    return; // collapsed face (repeated corners), or the line lies in it
  }
  float v[2];
  int nv = 0;
  if (fabsf(k2) <= 1e-6f * scale)
  {
    if (k1 != 0.0f)
    {
      v[nv++] = -k0 / k1;
    }
  }
  else
  {
    const float disc = k1 * k1 - 4.0f * k2 * k0;
    if (disc < 0.0f)
    {
      return;
    }
    const float q = -0.5f * (k1 + copysignf(sqrtf(disc), k1));
    v[nv++] = q / k2;
    if (q != 0.0f)
    {
      v[nv++] = k0 / q;
    }
  }
  const glm::vec3 e3 = b - a, f3 = dc - a, g3 = a - b + c - dc;
  const float dd = glm::dot(d, d);
  for (int i = 0; i < nv && count < kElementChordBreaks; ++i)
  {
    // u from the better conditioned component of H - v F = u (E + v G).
    const glm::vec2 den = E + v[i] * G, num = H - v[i] * F;
    const float u =
      fabsf(den.x) >= fabsf(den.y) ? (den.x != 0.0f ? num.x / den.x : 0.0f) : num.y / den.y;
    const glm::vec3 x = a + u * e3 + v[i] * f3 + u * v[i] * g3;
    const float t = glm::dot(x - p0, d) / dd;
    if (t == t)
    {
      breaks[count++] = t;
    }
  }
}

/// Breakpoints of element kind `kind` (corners v in its frame, mesh/ElementList.h's VTK order)
/// along p0 + t d (p0 near the element: the patch roots are solved relative to it). Returns the
/// count, at most kElementChordBreaks; 0 for a kind outside the list.
AMRDM_HD int elementBreaks(int kind,
  const glm::vec4* v,
  const glm::vec3& p0,
  const glm::vec3& d,
  float* breaks)
{
  // Faces as corner lists (local arrays: no static data in device code); triangles end in -1.
  const int kTet[4][4] = { { 0, 1, 3, -1 }, { 1, 2, 3, -1 }, { 2, 0, 3, -1 }, { 0, 2, 1, -1 } };
  const int kPyramid[5][4] = {
    { 0, 1, 2, 3 }, { 0, 1, 4, -1 }, { 1, 2, 4, -1 }, { 2, 3, 4, -1 }, { 3, 0, 4, -1 }
  };
  const int kWedge[5][4] = {
    { 0, 1, 2, -1 }, { 3, 4, 5, -1 }, { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 2, 0, 3, 5 }
  };
  const int kHex[6][4] = {
    { 0, 1, 2, 3 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 }
  };
  const int(*faces)[4] = nullptr;
  int numFaces = 0;
  switch (kind)
  {
    case int(ElementKind::Tet):
      faces = kTet;
      numFaces = 4;
      break;
    case int(ElementKind::Pyramid):
      faces = kPyramid;
      numFaces = 5;
      break;
    case int(ElementKind::Wedge):
      faces = kWedge;
      numFaces = 5;
      break;
    case int(ElementKind::Hex):
      faces = kHex;
      numFaces = 6;
      break;
    default:
      return 0;
  }
  // An orthonormal pair perpendicular to d.
  const glm::vec3 dn = glm::normalize(d);
  const glm::vec3 helper =
    fabsf(dn.x) < 0.6f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 u1 = glm::normalize(glm::cross(dn, helper));
  const glm::vec3 u2 = glm::cross(dn, u1);
  int count = 0;
  for (int f = 0; f < numFaces; ++f)
  {
    const glm::vec3 a(v[faces[f][0]]), b(v[faces[f][1]]), c(v[faces[f][2]]);
    if (faces[f][3] < 0)
    {
      addPlaneBreak(glm::cross(b - a, c - a), a, p0, d, breaks, count);
    }
    else
    {
      addQuadBreaks(a, b, c, glm::vec3(v[faces[f][3]]), p0, d, u1, u2, breaks, count);
    }
  }
  return count;
}

/// The pieces of [t0, t1] (in ray order) that element kind `kind` (corners v) claims along
/// q0 + t d, each [lo[i], hi[i]] with claimed ends: the element's breakpoints cut [t0, t1], each
/// piece's midpoint is tested, claimed neighbours are merged, and an end the element does not
/// claim at its breakpoint (its tolerance on the wrong side by rounding) is moved inside by
/// bisection toward the midpoint. Returns the number of pieces.
template<typename Claims>
AMRDM_HD int elementChord(int kind,
  const glm::vec4* v,
  const glm::vec3& q0,
  const glm::vec3& d,
  float t0,
  float t1,
  Claims&& claims,
  float* lo,
  float* hi)
{
  float cut[kElementChordBreaks + 2];
  const glm::vec3 p0 = q0 + t0 * d; // the line's origin moved next to the element
  int n = elementBreaks(kind, v, p0, d, cut);
  int m = 0;
  for (int i = 0; i < n; ++i)
  {
    const float t = t0 + cut[i];
    if (t > t0 && t < t1)
    {
      cut[m++] = t;
    }
  }
  cut[m++] = t0;
  cut[m++] = t1;
  for (int i = 1; i < m; ++i) // insertion sort: at most 20
  {
    const float x = cut[i];
    int j = i - 1;
    for (; j >= 0 && cut[j] > x; --j)
    {
      cut[j + 1] = cut[j];
    }
    cut[j + 1] = x;
  }
  int unique = 1;
  for (int i = 1; i < m; ++i)
  {
    if (cut[i] > cut[unique - 1])
    {
      cut[unique++] = cut[i];
    }
  }
  m = unique;
  // An end the element does not claim at its breakpoint (its tolerance on the wrong side by
  // rounding) is moved toward `inside` (a claimed midpoint) by bisection.
  auto settle = [&](float end, float inside)
  {
    if (claims(end))
    {
      return end;
    }
    float out = end;
    for (int k = 0; k < 24; ++k)
    {
      const float h = 0.5f * (out + inside);
      (claims(h) ? inside : out) = h;
    }
    return inside;
  };
  int pieces = 0;
  bool open = false;
  float midFirst = 0.0f, midLast = 0.0f;
  for (int i = 0; i + 1 < m && pieces < kElementChordPieces; ++i)
  {
    const float a = cut[i], b = cut[i + 1];
    const float mi = 0.5f * (a + b);
    const bool in = claims(mi);
    if (in)
    {
      if (!open)
      {
        lo[pieces] = a;
        midFirst = mi;
        open = true;
      }
      hi[pieces] = b;
      midLast = mi;
    }
    if (open && (!in || i + 2 == m))
    {
      lo[pieces] = settle(lo[pieces], midFirst);
      hi[pieces] = settle(hi[pieces], midLast);
      ++pieces;
      open = false;
    }
  }
  return pieces;
}

} // namespace amrdm
