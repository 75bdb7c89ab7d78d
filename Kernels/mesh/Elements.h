// Point tests of the stitching elements (tet, pyramid, wedge, hex) of the AMR dual mesh.
// Host/device code, C++17 + GLM, no VTK. Corners are glm::vec4 (x, y, z, scalar) in VTK order;
// either handedness is accepted. Shape functions live in ElementShapes.h.
//
// Tets are linear: closed-form barycentric coordinates.
// Pyramids, wedges and hexes have two tests (ElementTestParams::test):
//  * Bilinear: the exact dual-mesh interpolant. The iso-parametric map x(r,s,t) = Σ N_i x_i is
//    inverted by Newton's method (the scheme OpenVKL and owlExaStitcher use), in the element's
//    local frame (ElementShapes.h) so that every tolerance below is relative to the element.
//  * PlanarFaces: no iteration. Every quad face is replaced by a plane; parametric coordinates
//    come from distance ratios between opposite faces. Exact for parallelepiped hexes, pyramids
//    with a parallelogram base, and wedges with parallel triangles and planar sides; an
//    approximation (cheaper, no convergence issues) elsewhere.
//
// Result of the Bilinear test (ElementSample; the sample* functions return `inside` and write
// `value` only when inside). Let pc be the last Newton iterate and d the distance from p of the
// point that pc clamped to the reference element maps to.
//  * Converged (an update below kNewtonConverged within maxNewtonIterations) and pc in the
//    reference element up to kInsideTolerance: inside; value = interpolant at pc (after the
//    last update).
//  * Otherwise the element still claims p if d <= kInsideDistance (p lies on the element within
//    float precision: keeps pyramid apexes and collapsed hex edges crack-free), or if Newton did
//    not converge (budget spent, or the Jacobian became singular on the way) but pc is in the
//    reference element up to kInsideTolerance and d <= kResidualTolerance. The value is then the
//    interpolant at the clamped pc, so it always lies within the range of the corner values;
//    `converged` stays false when Newton did not converge.
//  * Degenerate element (no extent, or singular Jacobian at the parametric centre) or diverged
//    iterate (|pcoord| > kNewtonDiverged): not inside.
// Whenever the value is not the exact-pc one above, ElementSample::value is the interpolant at the
// clamped pc (also for points not inside: diagnostics only).
//
// Result of the PlanarFaces test: inside iff p is on the inner side of every face plane (faces
// collapsed to a segment or point have none) up to kPlanarInsideTolerance; value = interpolant at
// the distance-ratio pcoords; converged = true, iterations = 0. An element without usable face
// pairs (flat, or collapsed too far) claims nothing.
#pragma once

#include "core/Tolerances.h"
#include "mesh/ElementShapes.h"
#include "mesh/ElementTest.h"

namespace amrdm
{

// The element tests' tolerances (kNewtonConverged, kInsideDistance, kSingularJacobian, ...)
// are in core/Tolerances.h with the ones that keep majorants and culling conservative.

/// Full result of one element test (tests and debugging); see the header comment.
struct ElementSample
{
  bool inside;       ///< the element claims the point
  bool converged;    ///< Newton converged (always true for PlanarFaces on a valid element)
  float value;       ///< interpolated scalar
  glm::vec3 pcoords; ///< last parametric coordinates (VTK convention), not clamped
  int iterations;    ///< Newton updates done (0 for PlanarFaces)
};

// --- Tets --------------------------------------------------------------------------------------

/// Closed-form barycentric test. False for points outside and for flat tets (never NaN).
AMRDM_HD bool sampleTet(const glm::vec4* v, const glm::vec3& p, float& value)
{
  LocalElement<4> e;
  if (!makeLocalElement(v, p, e))
  {
    return false;
  }
  const glm::vec3 e1 = e.x[1], e2 = e.x[2], e3 = e.x[3], d = e.q; // e.x[0] is the origin
  const glm::vec3 c23 = glm::cross(e2, e3);
  const float det = glm::dot(e1, c23);
  const float scale = glm::length(e1) * glm::length(e2) * glm::length(e3);
  if (!(glm::abs(det) > kSingularJacobian * scale))
  {
    return false;
  }
  // Dividing by the signed determinant makes the coordinates independent of orientation.
  const float b1 = glm::dot(d, c23) / det;
  const float b2 = glm::dot(e1, glm::cross(d, e3)) / det;
  const float b3 = glm::dot(e1, glm::cross(e2, d)) / det;
  const float b0 = 1.0f - b1 - b2 - b3;
  if (!(b0 >= -kInsideTolerance && b1 >= -kInsideTolerance && b2 >= -kInsideTolerance &&
        b3 >= -kInsideTolerance))
  {
    return false;
  }
  // Relative to corner 0 (as interpolateValue): a constant field stays exactly constant.
  value = e.f[0] + (b1 * (e.f[1] - e.f[0]) + b2 * (e.f[2] - e.f[0]) + b3 * (e.f[3] - e.f[0]));
  return true;
}

/// The element list's signature (mesh/ElementList.h): a tet has one test, `params` is unused.
AMRDM_HD bool sampleTet(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& /*params*/,
  float& value)
{
  return sampleTet(v, p, value);
}

// --- Shared tail of both tests ----------------------------------------------------------------

template<class Shape, int N>
AMRDM_HD float interpolateValue(const LocalElement<N>& e, const glm::vec3& pc)
{
  float w[N];
  Shape::weights(pc, w);
  // f0 + sum_i w_i (f_i - f0) equals sum_i w_i f_i (the weights sum to 1) but is exact for a
  // constant field, whatever the rounding of the weights.
  float sum = 0.0f;
  for (int i = 1; i < N; ++i)
  {
    sum += w[i] * (e.f[i] - e.f[0]);
  }
  return e.f[0] + sum;
}

/// Value at pc when `exact`, else at pc clamped to the reference element (header comment).
template<class Shape, int N>
AMRDM_HD ElementSample makeSample(const LocalElement<N>& e,
  const glm::vec3& pc,
  bool inside,
  bool exact,
  int iterations,
  bool converged)
{
  const float value = interpolateValue<Shape>(e, exact ? pc : Shape::clampToReference(pc));
  return ElementSample{ inside, converged, value, pc, iterations };
}

// --- Bilinear: Newton inversion of the iso-parametric map ---------------------------------------

template<class Shape>
AMRDM_HD ElementSample newtonEvaluate(const glm::vec4* v, const glm::vec3& p, int maxIterations)
{
  constexpr int N = Shape::kCorners;
  LocalElement<N> e;
  if (!makeLocalElement(v, p, e))
  {
    return ElementSample{ false, false, 0.0f, Shape::center(), 0 };
  }
  maxIterations = glm::clamp(maxIterations, 1, 64);
  glm::vec3 pc = Shape::center();
  bool converged = false;
  int it = 0;
  for (; it < maxIterations; ++it)
  {
    float w[N];
    glm::vec3 dw[N];
    Shape::weights(pc, w);
    Shape::derivatives(pc, dw);
    glm::vec3 F = -e.q, jr(0.0f), js(0.0f), jt(0.0f);
    for (int i = 0; i < N; ++i)
    {
      F += w[i] * e.x[i];
      jr += dw[i].x * e.x[i];
      js += dw[i].y * e.x[i];
      jt += dw[i].z * e.x[i];
    }
    const glm::vec3 cst = glm::cross(js, jt);
    const float det = glm::dot(jr, cst);
    const float scale = glm::length(jr) * glm::length(js) * glm::length(jt);
    if (!(glm::abs(det) > kSingularJacobian * scale))
    {
      if (it == 0)
      {
        // Singular at the centre: a flat element. It claims nothing.
        return makeSample<Shape>(e, pc, false, false, 0, false);
      }
      break; // singular on the way (apex, collapsed corner): decide by the residual below
    }
    // Cramer's rule for J * delta = F, J = [jr js jt].
    const glm::vec3 delta =
      glm::vec3(
        glm::dot(F, cst), glm::dot(jr, glm::cross(F, jt)), glm::dot(jr, glm::cross(js, F))) /
      det;
    const glm::vec3 next = pc - delta;
    if (!(glm::abs(next.x) <= kNewtonDiverged && glm::abs(next.y) <= kNewtonDiverged &&
          glm::abs(next.z) <= kNewtonDiverged))
    {
      return makeSample<Shape>(
        e, pc, false, false, it, false); // diverged (or NaN): keep last finite
    }
    pc = next;
    if (glm::abs(delta.x) < kNewtonConverged && glm::abs(delta.y) < kNewtonConverged &&
        glm::abs(delta.z) < kNewtonConverged)
    {
      converged = true;
      ++it;
      break;
    }
  }
  // Distance from p of the point the clamped pcoords map to (computed only where needed).
  const auto clampedDistance = [&]()
  {
    float w[N];
    Shape::weights(Shape::clampToReference(pc), w);
    return glm::length(interpolateCorners<N>(w, e.x) - e.q);
  };
  const bool inRef = Shape::inReference(pc, kInsideTolerance);
  bool inside = inRef && converged;
  if (!inside)
  {
    const float d = clampedDistance();
    inside = d <= kInsideDistance || (inRef && d <= kResidualTolerance);
  }
  return makeSample<Shape>(e, pc, inside, converged && inRef, it, converged);
}

// --- PlanarFaces: distance ratios between face planes -----------------------------------------

/// A face plane with unit normal pointing into the element. `valid` is false for a face that
/// collapsed to a segment or a point.
struct FacePlane
{
  glm::vec3 n;
  glm::vec3 c;
  bool valid;
};

AMRDM_HD float faceDistance(const FacePlane& f, const glm::vec3& x)
{
  return glm::dot(f.n, x - f.c);
}

AMRDM_HD FacePlane orientedPlane(const glm::vec3& n, const glm::vec3& c, const glm::vec3& inner)
{
  const float len = glm::length(n);
  if (!(len > kDegenerateFace))
  {
    return FacePlane{ glm::vec3(0.0f), c, false };
  }
  const glm::vec3 u = n / len;
  return FacePlane{ glm::dot(u, inner - c) < 0.0f ? -u : u, c, true };
}

/// Quad a-b-c-d (in loop order): plane through its centroid, normal = cross of the diagonals.
AMRDM_HD FacePlane quadPlane(const glm::vec3& a,
  const glm::vec3& b,
  const glm::vec3& c,
  const glm::vec3& d,
  const glm::vec3& inner)
{
  return orientedPlane(glm::cross(c - a, d - b), 0.25f * (a + b + c + d), inner);
}

AMRDM_HD FacePlane triPlane(const glm::vec3& a,
  const glm::vec3& b,
  const glm::vec3& c,
  const glm::vec3& inner)
{
  return orientedPlane(glm::cross(b - a, c - a), (a + b + c) * (1.0f / 3.0f), inner);
}

/// Normalised distance from face f to q, in units of f's distance to `opposite` (a point on the
/// opposite side of the element). False when that distance vanishes.
AMRDM_HD bool faceRatio(const FacePlane& f, const glm::vec3& opposite, const glm::vec3& q, float& a)
{
  const float h = faceDistance(f, opposite);
  if (!(h > kDegenerateFace))
  {
    return false;
  }
  a = faceDistance(f, q) / h;
  return true;
}

/// Parameter between face f0 (param 0) and face f1 (param 1): a / (a + b) with a, b the
/// normalised distances to f0 and f1. `on1` / `on0` are points on f1 / f0 (centroids of their
/// corners that are not shared with the other face). With one face collapsed, the other face
/// alone gives the parameter. Where both distances vanish (their intersection line, e.g. the
/// pyramid apex) the interpolant does not depend on the parameter and 0.5 is returned.
AMRDM_HD bool pairParameter(const FacePlane& f0,
  const FacePlane& f1,
  const glm::vec3& on0,
  const glm::vec3& on1,
  const glm::vec3& q,
  float& param)
{
  float a = 0.0f, b = 0.0f;
  const bool ok0 = f0.valid && faceRatio(f0, on1, q, a);
  const bool ok1 = f1.valid && faceRatio(f1, on0, q, b);
  if (ok0 && ok1)
  {
    const float sum = a + b;
    param = glm::abs(sum) > kDegenerateFace ? a / sum : 0.5f;
    return true;
  }
  param = ok0 ? a : 1.0f - b;
  return ok0 || ok1;
}

AMRDM_HD bool insideAllPlanes(const FacePlane* f, int count, const glm::vec3& q)
{
  for (int i = 0; i < count; ++i)
  {
    if (f[i].valid && !(faceDistance(f[i], q) >= -kPlanarInsideTolerance))
    {
      return false;
    }
  }
  return true;
}

template<int N>
AMRDM_HD glm::vec3 cornerCentroid(const LocalElement<N>& e)
{
  glm::vec3 c = e.x[0];
  for (int i = 1; i < N; ++i)
  {
    c += e.x[i];
  }
  return c * (1.0f / float(N));
}

/// Planar-face pcoords of a hex. False when the element has no usable face pair.
AMRDM_HD bool planarPcoords(const LocalElement<8>& e, glm::vec3& pc, bool& inside)
{
  const glm::vec3* x = e.x;
  const glm::vec3 g = cornerCentroid(e);
  const FacePlane f[6] = {
    quadPlane(x[0], x[3], x[7], x[4], g), // r = 0
    quadPlane(x[1], x[2], x[6], x[5], g), // r = 1
    quadPlane(x[0], x[1], x[5], x[4], g), // s = 0
    quadPlane(x[3], x[2], x[6], x[7], g), // s = 1
    quadPlane(x[0], x[1], x[2], x[3], g), // t = 0
    quadPlane(x[4], x[5], x[6], x[7], g), // t = 1
  };
  const glm::vec3 c[6] = { 0.25f * (x[0] + x[3] + x[7] + x[4]),
    0.25f * (x[1] + x[2] + x[6] + x[5]),
    0.25f * (x[0] + x[1] + x[5] + x[4]),
    0.25f * (x[3] + x[2] + x[6] + x[7]),
    0.25f * (x[0] + x[1] + x[2] + x[3]),
    0.25f * (x[4] + x[5] + x[6] + x[7]) };
  inside = insideAllPlanes(f, 6, e.q);
  return pairParameter(f[0], f[1], c[0], c[1], e.q, pc.x) &&
         pairParameter(f[2], f[3], c[2], c[3], e.q, pc.y) &&
         pairParameter(f[4], f[5], c[4], c[5], e.q, pc.z);
}

/// Planar-face pcoords of a pyramid: r, s from opposite side faces, t from the base plane.
AMRDM_HD bool planarPcoords(const LocalElement<5>& e, glm::vec3& pc, bool& inside)
{
  const glm::vec3* x = e.x;
  const glm::vec3 g = cornerCentroid(e);
  const FacePlane f[5] = {
    triPlane(x[0], x[3], x[4], g),        // r = 0
    triPlane(x[1], x[2], x[4], g),        // r = 1
    triPlane(x[0], x[1], x[4], g),        // s = 0
    triPlane(x[3], x[2], x[4], g),        // s = 1
    quadPlane(x[0], x[1], x[2], x[3], g), // t = 0 (base)
  };
  inside = insideAllPlanes(f, 5, e.q);
  bool ok = f[0].valid && f[1].valid && f[2].valid && f[3].valid;
  ok = ok && pairParameter(f[0], f[1], 0.5f * (x[0] + x[3]), 0.5f * (x[1] + x[2]), e.q, pc.x);
  ok = ok && pairParameter(f[2], f[3], 0.5f * (x[0] + x[1]), 0.5f * (x[3] + x[2]), e.q, pc.y);
  return ok && f[4].valid && faceRatio(f[4], x[4], e.q, pc.z);
}

/// Planar-face pcoords of a wedge: barycentric (r, s) from the three side faces, each distance
/// normalised by that of the opposite edge, then scaled to sum to one; t between the triangles.
AMRDM_HD bool planarPcoords(const LocalElement<6>& e, glm::vec3& pc, bool& inside)
{
  const glm::vec3* x = e.x;
  const glm::vec3 g = cornerCentroid(e);
  const FacePlane f[5] = {
    quadPlane(x[0], x[2], x[5], x[3], g), // r = 0, opposite edge 1-4
    quadPlane(x[0], x[1], x[4], x[3], g), // s = 0, opposite edge 2-5
    quadPlane(x[1], x[2], x[5], x[4], g), // r + s = 1, opposite edge 0-3
    triPlane(x[0], x[1], x[2], g),        // t = 0
    triPlane(x[3], x[4], x[5], g),        // t = 1
  };
  inside = insideAllPlanes(f, 5, e.q);
  float br = 0.0f, bs = 0.0f, bu = 0.0f;
  const bool ok = f[0].valid && f[1].valid && f[2].valid &&
                  faceRatio(f[0], 0.5f * (x[1] + x[4]), e.q, br) &&
                  faceRatio(f[1], 0.5f * (x[2] + x[5]), e.q, bs) &&
                  faceRatio(f[2], 0.5f * (x[0] + x[3]), e.q, bu);
  const float sum = br + bs + bu;
  if (!ok || !(glm::abs(sum) > kDegenerateFace))
  {
    return false;
  }
  pc.x = br / sum;
  pc.y = bs / sum;
  return pairParameter(f[3],
    f[4],
    (x[0] + x[1] + x[2]) * (1.0f / 3.0f),
    (x[3] + x[4] + x[5]) * (1.0f / 3.0f),
    e.q,
    pc.z);
}

template<class Shape>
AMRDM_HD ElementSample planarEvaluate(const glm::vec4* v, const glm::vec3& p)
{
  LocalElement<Shape::kCorners> e;
  glm::vec3 pc = Shape::center();
  bool inside = false;
  if (!makeLocalElement(v, p, e))
  {
    return ElementSample{ false, false, 0.0f, pc, 0 };
  }
  if (!planarPcoords(e, pc, inside))
  {
    return makeSample<Shape>(e, Shape::center(), false, false, 0, false); // degenerate
  }
  return makeSample<Shape>(e, pc, inside, inside, 0, true);
}

// --- Public entry points ----------------------------------------------------------------------

template<class Shape>
AMRDM_HD ElementSample evaluateElement(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params)
{
  return params.test == ElementTest::PlanarFaces
           ? planarEvaluate<Shape>(v, p)
           : newtonEvaluate<Shape>(v, p, params.maxNewtonIterations);
}

/// Pyramid corners 0-3 base (may be twisted), 4 apex.
AMRDM_HD ElementSample evaluatePyramid(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params)
{
  return evaluateElement<PyramidShape>(v, p, params);
}

/// Wedge corners: triangle 0,1,2 and triangle 3,4,5 (3 above 0, ...).
AMRDM_HD ElementSample evaluateWedge(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params)
{
  return evaluateElement<WedgeShape>(v, p, params);
}

/// Hex corners 0-3 bottom, 4-7 top (VTK_HEXAHEDRON); repeated corners are allowed.
AMRDM_HD ElementSample evaluateHex(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params)
{
  return evaluateElement<HexShape>(v, p, params);
}

template<class Shape>
AMRDM_HD bool sampleElement(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params,
  float& value)
{
  const ElementSample s = evaluateElement<Shape>(v, p, params);
  if (s.inside)
  {
    value = s.value;
  }
  return s.inside;
}

AMRDM_HD bool samplePyramid(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params,
  float& value)
{
  return sampleElement<PyramidShape>(v, p, params, value);
}

AMRDM_HD bool sampleWedge(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params,
  float& value)
{
  return sampleElement<WedgeShape>(v, p, params, value);
}

AMRDM_HD bool sampleHex(const glm::vec4* v,
  const glm::vec3& p,
  const ElementTestParams& params,
  float& value)
{
  return sampleElement<HexShape>(v, p, params, value);
}

} // namespace amrdm
