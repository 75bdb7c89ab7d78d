// The double-precision oracle of the element tests (Testing/Kernels/mesh/TestElements*.cxx):
// shape functions, forward map and its Newton inverse written independently of the kernels; the
// unit cells, their affine (scaled, translated, mirrored, sheared) and twisted copies; the
// forward-mapped point test that compares the kernels' inside test, value and pcoords with it.
// The corners and reference distances are ElementReference.h's, shared with TestElementOracle.
#pragma once

#include "ElementReference.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace amrdm_test
{
using amrdm::elementCorners;
using amrdm::ElementSample;
using amrdm::ElementTest;
using amrdm::ElementTestParams;
using glm::dvec3;

/// Value tolerance relative to the corner-value range (the project's 1e-5).
constexpr double kValueTolerance = 1e-5;
/// Points closer than this to a face (unit-cell lengths, or parametric units for forward-mapped
/// points) are only counted: there either answer is right within float precision.
constexpr double kFaceBand = 1e-4;
/// Pcoords recovered by the Newton test must match the generating ones this closely.
constexpr double kPcoordTolerance = 1e-4;
constexpr int kPoints = 4000;

// What is written here per kind is the double-precision oracle (shape functions, twisted cells),
// so a kind added to mesh/ElementList.h fails ElementReference.h's static_assert until it has one.
using Kind = int;

inline void shapeD(Kind k, const dvec3& c, double* w)
{
  const double r = c.x, s = c.y, t = c.z;
  switch (k)
  {
    case kTet:
      w[0] = 1 - r - s - t, w[1] = r, w[2] = s, w[3] = t;
      break;
    case kPyramid:
      w[0] = (1 - r) * (1 - s) * (1 - t), w[1] = r * (1 - s) * (1 - t), w[2] = r * s * (1 - t);
      w[3] = (1 - r) * s * (1 - t), w[4] = t;
      break;
    case kWedge:
      w[0] = (1 - r - s) * (1 - t), w[1] = r * (1 - t), w[2] = s * (1 - t);
      w[3] = (1 - r - s) * t, w[4] = r * t, w[5] = s * t;
      break;
    case kHex:
      for (int i = 0; i < 8; ++i)
      {
        const double a = (i % 4 == 1 || i % 4 == 2) ? r : 1 - r;
        const double b = (i % 4 >= 2) ? s : 1 - s;
        w[i] = a * b * (i >= 4 ? t : 1 - t);
      }
      break;
  }
}

struct Element
{
  Kind kind;
  std::vector<dvec3> x;  ///< corners (double)
  std::vector<double> f; ///< corner values
  dvec3 map(const dvec3& pc) const
  {
    double w[8];
    shapeD(kind, pc, w);
    dvec3 p(0.0);
    for (int i = 0; i < elementCorners(kind); ++i)
      p += w[i] * x[i];
    return p;
  }
  double value(const dvec3& pc) const
  {
    double w[8], v = 0.0;
    shapeD(kind, pc, w);
    for (int i = 0; i < elementCorners(kind); ++i)
      v += w[i] * f[i];
    return v;
  }
  double range() const
  {
    return *std::max_element(f.begin(), f.end()) - *std::min_element(f.begin(), f.end());
  }
  std::vector<glm::vec4> corners() const
  {
    std::vector<glm::vec4> v;
    for (int i = 0; i < elementCorners(kind); ++i)
      v.emplace_back(toFloat(x[i]), float(f[i]));
    return v;
  }
  /// Pcoords of p by Newton in double with a central-difference Jacobian, from `start`.
  dvec3 invert(const dvec3& p, dvec3 pc) const
  {
    for (int it = 0; it < 50; ++it)
    {
      glm::dmat3 J;
      for (int d = 0; d < 3; ++d)
      {
        dvec3 h(0.0);
        h[d] = 1e-6;
        J[d] = (map(pc + h) - map(pc - h)) / 2e-6;
      }
      if (!(std::abs(glm::determinant(J)) > 1e-300))
        break; // exactly at a pyramid apex or a collapsed corner: pc is as good as any
      const dvec3 delta = glm::inverse(J) * (map(pc) - p);
      pc -= delta;
      if (glm::length(delta) < 1e-13)
        break;
    }
    return pc;
  }
};

/// The unit cells; corner pcoords are the corners themselves except for the pyramid apex.
inline Element unitCell(Kind k)
{
  return Element{ k, unitCorners(k), {} };
}

/// Signed distance of unit-cell point u to the unit cell's boundary (half-spaces, positive inside).
inline double unitCellDistance(Kind k, const dvec3& u)
{
  double d = std::min({ u.x, u.y, u.z });
  const double s5 = std::sqrt(1.25);
  switch (k)
  {
    case kTet:
      return std::min(d, (1 - u.x - u.y - u.z) / std::sqrt(3.0));
    case kPyramid:
      return std::min({ u.z,
        (u.x - 0.5 * u.z) / s5,
        (1 - 0.5 * u.z - u.x) / s5,
        (u.y - 0.5 * u.z) / s5,
        (1 - 0.5 * u.z - u.y) / s5 });
    case kWedge:
      return std::min({ d, (1 - u.x - u.y) / std::sqrt(2.0), 1 - u.z });
    default:
      return std::min({ d, 1 - u.x, 1 - u.y, 1 - u.z });
  }
}

/// x = offset + A u.
struct Affine
{
  const char* name;
  glm::dmat3 A;
  dvec3 offset;
};

inline std::vector<Affine> affines()
{
  const glm::dmat3 I(1.0);
  // A shear with negative determinant: a mirrored parallelepiped.
  const glm::dmat3 shear(
    glm::dvec3(1.0, 0.2, -0.1), glm::dvec3(0.3, -0.9, 0.2), glm::dvec3(0.15, 0.25, 1.3));
  return { { "unit", I, dvec3(0.0) },
    { "scaled 1e-6", 1e-6 * I, dvec3(0.0) },
    { "scaled 1e6", 1e6 * I, dvec3(0.0) },
    { "offset 1e6", I, dvec3(1e6, -1e6, 1e6) },
    { "mirrored",
      glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)),
      dvec3(0.0) },
    { "sheared+mirrored", shear, dvec3(0.0) },
    { "sheared 1e3 at offset 1e6", 1e3 * shear, dvec3(-1e6, 1e6, 1e6) },
    { "sheared 1e-6 at offset 1e-5", 1e-6 * shear, dvec3(1e-5, -2e-5, 3e-5) } };
}

/// The corners are rounded to float: the element under test is the one the kernels see.
inline Element transformed(const Element& e, const Affine& a)
{
  Element t = e;
  for (auto& x : t.x)
    x = dvec3(toFloat(a.offset + a.A * x));
  return t;
}

inline ElementTestParams paramsFor(ElementTest test, int iterations = 10)
{
  ElementTestParams prm;
  prm.test = test;
  prm.maxNewtonIterations = iterations;
  return prm;
}

inline std::string testName(ElementTest t)
{
  return t == ElementTest::Bilinear ? "Bilinear" : "PlanarFaces";
}

/// Random pcoords in the reference element grown by `margin`.
inline dvec3 randomPcoords(std::mt19937& rng, Kind k, double margin)
{
  std::uniform_real_distribution<double> u(-margin, 1.0 + margin);
  for (;;)
  {
    const dvec3 c(u(rng), u(rng), u(rng));
    if (referenceDistance(k, c) >= -margin)
      return c;
  }
}

/// Moderately twisted cells: one vertex of a quad face moved out of its plane.
inline Element twistedCell(Kind k)
{
  Element e = unitCell(k);
  switch (k)
  {
    case kPyramid:
      e.x[2] += dvec3(0.0, 0.0, 0.3); // non-planar base
      e.x[4] = dvec3(0.3, 0.6, 1.0);  // off-centre apex
      break;
    case kWedge:
      e.x[4] += dvec3(0.0, 0.2, 0.3); // quads 0-1-4-3 and 1-2-5-4 twisted
      break;
    case kHex:
      e.x[6] += dvec3(0.1, 0.1, 0.35); // top, r = 1 and s = 1 faces twisted
      break;
    default:
      break;
  }
  return e;
}

/// Top face rotated by 60 degrees about the vertical axis: every side face strongly twisted.
inline Element stronglyTwistedHex()
{
  Element e = unitCell(kHex);
  const double a = 3.14159265358979 / 3.0;
  for (int i = 4; i < 8; ++i)
  {
    const dvec3 d = e.x[i] - dvec3(0.5, 0.5, 1.0);
    e.x[i] = dvec3(0.5 + std::cos(a) * d.x - std::sin(a) * d.y,
      0.5 + std::sin(a) * d.x + std::cos(a) * d.y,
      1.0);
  }
  return e;
}

inline void randomValues(std::mt19937& rng, Element& e)
{
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  e.f.resize(e.x.size());
  for (auto& f : e.f)
    f = u(rng);
}

/// Forward-mapped points: pcoords sampled around the reference element, mapped in double, rounded
/// to float, then re-inverted in double (so the truth refers to the float point).
struct ForwardStats
{
  int inside = 0, outside = 0, band = 0, missed = 0, falseHits = 0, pcoordFails = 0;
  double maxValueError = 0.0, sumSq = 0.0;
  int compared = 0;
  double rms() const { return compared ? std::sqrt(sumSq / compared) : 0.0; }
  double misclassRate() const { return double(missed + falseHits) / std::max(1, inside + outside); }
};

inline ForwardStats forwardTest(const Element& e,
  const ElementTestParams& prm,
  unsigned seed,
  bool checkPcoords,
  double margin = 0.1)
{
  std::mt19937 rng(seed);
  ForwardStats st;
  const auto v = e.corners();
  const double range = e.range();
  for (int n = 0; n < kPoints; ++n)
  {
    const dvec3 c0 = randomPcoords(rng, e.kind, margin);
    const glm::vec3 p = toFloat(e.map(c0));
    const dvec3 c = e.invert(dvec3(p), c0);
    const double dist = referenceDistance(e.kind, c);
    const ElementSample s = evaluateElement(e.kind, v.data(), p, prm);
    if (std::abs(dist) < kFaceBand)
    {
      ++st.band;
      continue;
    }
    if (dist < 0)
    {
      ++st.outside;
      st.falseHits += s.inside ? 1 : 0;
      continue;
    }
    ++st.inside;
    if (!s.inside)
    {
      ++st.missed;
      continue;
    }
    const double err = std::abs(double(s.value) - e.value(c)) / range;
    st.maxValueError = std::max(st.maxValueError, err);
    st.sumSq += err * err;
    ++st.compared;
    // Near a pyramid apex (r, s) are ill-defined; only t is compared there.
    const bool nearApex = e.kind == kPyramid && c.z > 0.99;
    const dvec3 dc = glm::abs(dvec3(s.pcoords) - c);
    if (checkPcoords &&
        (dc.z > kPcoordTolerance || (!nearApex && std::max(dc.x, dc.y) > kPcoordTolerance)))
    {
      ++st.pcoordFails;
    }
  }
  return st;
}

} // namespace amrdm_test
