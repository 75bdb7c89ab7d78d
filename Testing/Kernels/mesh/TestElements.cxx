// Element tests (kernel only, no VTK), after OpenVKL's unstructured-volume sampling tests:
// unit cells of each type against analytic half-spaces and an analytic linear field, on scaled,
// translated, mirrored and sheared copies; twisted elements against the forward map; the
// PlanarFaces approximation measured on twisted cells; collapsed-corner hexes; the defined result
// when Newton does not converge; flat elements.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/ElementList.h"
#include "mesh/Elements.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace amrdm;
using glm::dvec3;

namespace
{
/// Value tolerance relative to the corner-value range (the project's 1e-5).
constexpr double kValueTolerance = 1e-5;
/// Points closer than this to a face (unit-cell lengths, or parametric units for forward-mapped
/// points) are only counted: there either answer is right within float precision.
constexpr double kFaceBand = 1e-4;
/// Pcoords recovered by the Newton test must match the generating ones this closely.
constexpr double kPcoordTolerance = 1e-4;
constexpr int kPoints = 4000;

// The element kinds, their names and corners come from mesh/ElementList.h (the one
// registration); what is written here per kind is the double-precision oracle (shape functions,
// unit and twisted cells), so a kind added to the list fails here until it has one.
using Kind = int;
constexpr Kind Tet = int(ElementKind::Tet), Pyramid = int(ElementKind::Pyramid),
               Wedge = int(ElementKind::Wedge), Hex = int(ElementKind::Hex);
static_assert(kElementKindCount == 4,
  "TestElements.cxx: write the double-precision oracle (shapeD, unitCell, twistedCell, "
  "referenceDistance, evaluate) of the new element kind of mesh/ElementList.h");

/// Rounds to float through volatile stores. GCC 12 at -O2 folds the vectorised round trip
/// dvec3(vec3(d)) back into d for some lanes, which would make the double "truth" refer to a
/// point the kernels never see.
glm::vec3 toFloat(const dvec3& d)
{
  volatile float x = static_cast<float>(d.x), y = static_cast<float>(d.y),
                 z = static_cast<float>(d.z);
  return glm::vec3(x, y, z);
}

// --- Double-precision reference: shape functions written independently of the kernels -------

void shapeD(Kind k, const dvec3& c, double* w)
{
  const double r = c.x, s = c.y, t = c.z;
  switch (k)
  {
    case Tet:
      w[0] = 1 - r - s - t, w[1] = r, w[2] = s, w[3] = t;
      break;
    case Pyramid:
      w[0] = (1 - r) * (1 - s) * (1 - t), w[1] = r * (1 - s) * (1 - t), w[2] = r * s * (1 - t);
      w[3] = (1 - r) * s * (1 - t), w[4] = t;
      break;
    case Wedge:
      w[0] = (1 - r - s) * (1 - t), w[1] = r * (1 - t), w[2] = s * (1 - t);
      w[3] = (1 - r - s) * t, w[4] = r * t, w[5] = s * t;
      break;
    case Hex:
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

/// Signed parametric distance to the reference element's boundary (positive inside). For the
/// pyramid, r and s are scaled by 1 - t: the side faces converge at the apex, and an unscaled
/// pcoord margin would vanish physically there.
double referenceDistance(Kind k, const dvec3& c)
{
  double d = std::min({ c.x, c.y, c.z });
  switch (k)
  {
    case Tet:
      return std::min(d, 1 - c.x - c.y - c.z);
    case Wedge:
      return std::min({ d, 1 - c.x - c.y, 1 - c.z });
    case Pyramid:
    {
      const double h = 1 - c.z;
      return std::min({ c.z, h, c.x * h, c.y * h, (1 - c.x) * h, (1 - c.y) * h });
    }
    default:
      return std::min({ d, 1 - c.x, 1 - c.y, 1 - c.z });
  }
}

/// The unit cells; corner pcoords are the corners themselves except for the pyramid apex.
Element unitCell(Kind k)
{
  Element e{ k, {}, {} };
  switch (k)
  {
    case Tet:
      e.x = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
      break;
    case Pyramid:
      e.x = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 } };
      break;
    case Wedge:
      e.x = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } };
      break;
    case Hex:
      e.x = { { 0, 0, 0 },
        { 1, 0, 0 },
        { 1, 1, 0 },
        { 0, 1, 0 },
        { 0, 0, 1 },
        { 1, 0, 1 },
        { 1, 1, 1 },
        { 0, 1, 1 } };
      break;
  }
  return e;
}

/// Signed distance of unit-cell point u to the unit cell's boundary (half-spaces, positive inside).
double unitCellDistance(Kind k, const dvec3& u)
{
  double d = std::min({ u.x, u.y, u.z });
  const double s5 = std::sqrt(1.25);
  switch (k)
  {
    case Tet:
      return std::min(d, (1 - u.x - u.y - u.z) / std::sqrt(3.0));
    case Pyramid:
      return std::min({ u.z,
        (u.x - 0.5 * u.z) / s5,
        (1 - 0.5 * u.z - u.x) / s5,
        (u.y - 0.5 * u.z) / s5,
        (1 - 0.5 * u.z - u.y) / s5 });
    case Wedge:
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

std::vector<Affine> affines()
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
Element transformed(const Element& e, const Affine& a)
{
  Element t = e;
  for (auto& x : t.x)
    x = dvec3(toFloat(a.offset + a.A * x));
  return t;
}

ElementSample evaluate(Kind k, const glm::vec4* v, const glm::vec3& p, const ElementTestParams& prm)
{
  switch (k)
  {
    case Tet:
    {
      float value = 0.0f;
      const bool in = sampleTet(v, p, value);
      return ElementSample{ in, true, value, glm::vec3(0.0f), 0 };
    }
    case Pyramid:
      return evaluatePyramid(v, p, prm);
    case Wedge:
      return evaluateWedge(v, p, prm);
    default:
      return evaluateHex(v, p, prm);
  }
}

ElementTestParams paramsFor(ElementTest test, int iterations = 10)
{
  ElementTestParams prm;
  prm.test = test;
  prm.maxNewtonIterations = iterations;
  return prm;
}

std::string testName(ElementTest t)
{
  return t == ElementTest::Bilinear ? "Bilinear" : "PlanarFaces";
}

/// Random pcoords in the reference element grown by `margin`.
dvec3 randomPcoords(std::mt19937& rng, Kind k, double margin)
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
Element twistedCell(Kind k)
{
  Element e = unitCell(k);
  switch (k)
  {
    case Pyramid:
      e.x[2] += dvec3(0.0, 0.0, 0.3); // non-planar base
      e.x[4] = dvec3(0.3, 0.6, 1.0);  // off-centre apex
      break;
    case Wedge:
      e.x[4] += dvec3(0.0, 0.2, 0.3); // quads 0-1-4-3 and 1-2-5-4 twisted
      break;
    case Hex:
      e.x[6] += dvec3(0.1, 0.1, 0.35); // top, r = 1 and s = 1 faces twisted
      break;
    default:
      break;
  }
  return e;
}

/// Top face rotated by 60 degrees about the vertical axis: every side face strongly twisted.
Element stronglyTwistedHex()
{
  Element e = unitCell(Hex);
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

void randomValues(std::mt19937& rng, Element& e)
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

ForwardStats forwardTest(const Element& e,
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
    const ElementSample s = evaluate(e.kind, v.data(), p, prm);
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
    const bool nearApex = e.kind == Pyramid && c.z > 0.99;
    const dvec3 dc = glm::abs(dvec3(s.pcoords) - c);
    if (checkPcoords &&
        (dc.z > kPcoordTolerance || (!nearApex && std::max(dc.x, dc.y) > kPcoordTolerance)))
    {
      ++st.pcoordFails;
    }
  }
  return st;
}

} // namespace

TEST_CASE("unit cells and affine copies: half-space truth and exact linear field")
{
  for (const Affine& a : affines())
  {
    int bandTotal = 0;
    double maxErrTotal = 0.0;
    for (int k = Tet; k < kElementKindCount; ++k)
    {
      for (ElementTest test : { ElementTest::Bilinear, ElementTest::PlanarFaces })
      {
        if (k == Tet && test == ElementTest::PlanarFaces)
          continue;
        const Kind kind = Kind(k);
        std::mt19937 rng(1234u + 17u * unsigned(k));
        std::uniform_real_distribution<double> u(-0.1, 1.1);
        // Linear field in unit-cell coordinates, hence also linear in physical coordinates.
        const dvec3 grad(0.7, -1.3, 2.1);
        const double offset = 0.4;
        Element e = transformed(unitCell(kind), a);
        const Element unit = unitCell(kind);
        for (const dvec3& x : unit.x)
          e.f.push_back(glm::dot(grad, x) + offset);
        const auto v = e.corners();
        const double range = e.range();
        const glm::dmat3 inv = glm::inverse(a.A);
        int band = 0, wrong = 0, inside = 0, nonFinite = 0;
        double maxErr = 0.0;
        for (int n = 0; n < kPoints; ++n)
        {
          const dvec3 u0(u(rng), u(rng), u(rng));
          const glm::vec3 p = toFloat(a.offset + a.A * u0);
          const dvec3 uu = inv * (dvec3(p) - a.offset); // the float point in unit coordinates
          const double dist = unitCellDistance(kind, uu);
          const ElementSample s = evaluate(kind, v.data(), p, paramsFor(test));
          if (std::abs(dist) < kFaceBand)
          {
            ++band;
            continue;
          }
          if (s.inside != (dist > 0))
          {
            ++wrong;
            continue;
          }
          if (s.inside)
          {
            ++inside;
            nonFinite += std::isfinite(s.value) ? 0 : 1;
            maxErr =
              std::max(maxErr, std::abs(double(s.value) - (glm::dot(grad, uu) + offset)) / range);
          }
        }
        INFO(std::string(a.name), " ", elementKindName(k), " ", testName(test));
        CHECK(wrong == 0);
        CHECK(nonFinite == 0);
        CHECK(inside > kPoints / 20);
        CHECK(maxErr <= kValueTolerance);
        bandTotal += band;
        maxErrTotal = std::max(maxErrTotal, maxErr);
      }
    }
    MESSAGE(std::string(a.name),
      ": 7 element/test pairs x ",
      kPoints,
      " points, ",
      bandTotal,
      " within ",
      kFaceBand,
      " of a face (not checked), max value error / range ",
      maxErrTotal);
  }
}

TEST_CASE("twisted elements, Bilinear: forward-mapped pcoords and values are recovered")
{
  for (const Affine& a : affines())
  {
    for (int k = Pyramid; k < kElementKindCount; ++k)
    {
      std::mt19937 rng(99u + unsigned(k));
      Element e = transformed(twistedCell(Kind(k)), a);
      randomValues(rng, e);
      const ForwardStats st = forwardTest(e, paramsFor(ElementTest::Bilinear), 7u + k, true);
      INFO(std::string(a.name), " twisted ", elementKindName(k));
      CHECK(st.missed == 0);
      CHECK(st.falseHits == 0);
      CHECK(st.pcoordFails == 0);
      CHECK(st.maxValueError <= kValueTolerance);
      CHECK(st.inside > kPoints / 3);
      if (std::string(a.name) == "unit")
        MESSAGE("Bilinear twisted ",
          elementKindName(k),
          ": max value error / range ",
          st.maxValueError,
          ", band ",
          st.band);
    }
  }
  // Every side face strongly twisted: still exact with the default 10 iterations.
  std::mt19937 rng(5u);
  Element e = stronglyTwistedHex();
  randomValues(rng, e);
  const ForwardStats st = forwardTest(e, paramsFor(ElementTest::Bilinear), 8u, true, 0.0);
  CHECK(st.missed == 0);
  CHECK(st.pcoordFails == 0);
  CHECK(st.maxValueError <= kValueTolerance);
}

TEST_CASE("PlanarFaces: exact on planar-faced elements, measured on twisted ones")
{
  std::mt19937 rng(321u);
  // Planar faces with parallel opposite faces or homothetic caps: exact by construction.
  std::vector<Element> planar;
  const glm::dmat3 shear(
    glm::dvec3(1.0, 0.2, -0.1), glm::dvec3(0.3, -0.9, 0.2), glm::dvec3(0.15, 0.25, 1.3));
  for (int k = Pyramid; k < kElementKindCount; ++k)
    planar.push_back(transformed(unitCell(Kind(k)), Affine{ "", shear, dvec3(3, -2, 1) }));
  Element skewApex = unitCell(Pyramid); // parallelogram base, apex anywhere above it
  skewApex.x[4] = dvec3(0.1, 0.9, 0.6);
  planar.push_back(transformed(skewApex, Affine{ "", shear, dvec3(0.0) }));
  Element frustum = unitCell(Wedge); // parallel triangles, top one shrunk: planar sides
  for (int i = 3; i < 6; ++i)
    frustum.x[i] =
      dvec3(1.0 / 3, 1.0 / 3, 1.0) + 0.6 * (frustum.x[i] - dvec3(1.0 / 3, 1.0 / 3, 1.0));
  planar.push_back(frustum);
  for (Element& e : planar)
  {
    randomValues(rng, e);
    const ForwardStats st = forwardTest(e, paramsFor(ElementTest::PlanarFaces), 11u, true);
    INFO("planar-faced ", elementKindName(e.kind));
    CHECK(st.missed == 0);
    CHECK(st.falseHits == 0);
    CHECK(st.pcoordFails == 0);
    CHECK(st.maxValueError <= kValueTolerance);
  }

  // Twisted: an approximation by design. Measure against the exact (Bilinear) interpolant.
  std::vector<std::pair<std::string, Element>> twisted;
  for (int k = Pyramid; k < kElementKindCount; ++k)
    twisted.emplace_back(std::string("twisted ") + elementKindName(k), twistedCell(Kind(k)));
  twisted.emplace_back("strongly twisted hex", stronglyTwistedHex());
  for (auto& [name, e] : twisted)
  {
    randomValues(rng, e);
    const double margin = name == "strongly twisted hex" ? 0.0 : 0.1;
    const ForwardStats st = forwardTest(e, paramsFor(ElementTest::PlanarFaces), 12u, false, margin);
    MESSAGE("PlanarFaces on ",
      name,
      ": max value error / range ",
      st.maxValueError,
      ", RMS ",
      st.rms(),
      ", misclassified ",
      st.missed + st.falseHits,
      " of ",
      st.inside + st.outside,
      " (",
      100.0 * st.misclassRate(),
      "%: ",
      st.missed,
      " missed, ",
      st.falseHits,
      " false hits), band ",
      st.band);
    CHECK(st.compared > 0);
  }
}

TEST_CASE("degenerate hexes with repeated corners sample away from the collapse")
{
  struct Case
  {
    const char* name;
    std::vector<std::pair<int, int>> collapse; // corner a := corner b
  };
  const Case cases[] = { { "vertical edge 2-6 collapsed", { { 6, 2 } } },
    { "top edge 6-7 collapsed", { { 7, 6 } } },
    { "face s=1 collapsed to a segment", { { 6, 2 }, { 7, 3 } } },
    { "corner 6 onto 5 and 7 onto 4, sheared", { { 6, 5 }, { 7, 4 } } } };
  std::mt19937 rng(77u);
  for (const Case& cs : cases)
  {
    Element e = unitCell(Hex);
    e.x[1] += dvec3(0.1, -0.05, 0.0); // not axis-aligned, not symmetric
    e.x[4] += dvec3(-0.1, 0.05, 0.05);
    for (auto [a, b] : cs.collapse)
      e.x[a] = e.x[b];
    randomValues(rng, e);
    for (auto [a, b] : cs.collapse)
      e.f[a] = e.f[b];
    for (ElementTest test : { ElementTest::Bilinear, ElementTest::PlanarFaces })
    {
      const ForwardStats st = forwardTest(e, paramsFor(test), 13u, false, 0.0);
      INFO(std::string(cs.name), " ", testName(test));
      CHECK(st.compared > 0);
      if (test == ElementTest::Bilinear)
      {
        CHECK(st.missed == 0);
        CHECK(st.maxValueError <= kValueTolerance);
      }
      MESSAGE("degenerate hex, ",
        std::string(cs.name),
        ", ",
        testName(test),
        ": max value error / range ",
        st.maxValueError,
        ", missed ",
        st.missed,
        " of ",
        st.inside,
        ", band ",
        st.band);
    }
  }
}

TEST_CASE("pyramid apex neighbourhood is claimed")
{
  Element e = twistedCell(Pyramid);
  std::mt19937 rng(4u);
  randomValues(rng, e);
  const auto v = e.corners();
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int missed = 0;
  double maxErr = 0.0;
  for (int n = 0; n < kPoints; ++n)
  {
    const dvec3 c(
      0.001 + 0.998 * u(rng), 0.001 + 0.998 * u(rng), 1.0 - std::pow(10.0, -1 - 5 * u(rng)));
    const glm::vec3 p = toFloat(e.map(c));
    const ElementSample s = evaluatePyramid(v.data(), p, paramsFor(ElementTest::Bilinear));
    if (!s.inside)
    {
      ++missed;
      continue;
    }
    maxErr =
      std::max(maxErr, std::abs(double(s.value) - e.value(e.invert(dvec3(p), c))) / e.range());
  }
  float value = 0.0f;
  CHECK(samplePyramid(v.data(), toFloat(e.x[4]), paramsFor(ElementTest::Bilinear), value));
  CHECK(std::abs(value - e.f[4]) <= kValueTolerance * e.range());
  CHECK(missed == 0);
  CHECK(maxErr <= kValueTolerance);
  MESSAGE(
    "pyramid apex (1-t in 1e-6..1e-1): missed ", missed, ", max value error / range ", maxErr);
}

TEST_CASE("Newton without convergence: defined result")
{
  std::mt19937 rng(8u);
  Element e = stronglyTwistedHex();
  randomValues(rng, e);
  const auto v = e.corners();
  const double lo = *std::min_element(e.f.begin(), e.f.end());
  const double hi = *std::max_element(e.f.begin(), e.f.end());
  int converged = 0, claimed = 0, outOfRange = 0, converged10 = 0;
  double maxErr = 0.0;
  for (int n = 0; n < kPoints; ++n)
  {
    const dvec3 c = randomPcoords(rng, Hex, 0.0);
    const glm::vec3 p = toFloat(e.map(c));
    const ElementSample s = evaluateHex(v.data(), p, paramsFor(ElementTest::Bilinear, 1));
    converged += s.converged ? 1 : 0;
    outOfRange += (s.value >= lo && s.value <= hi) ? 0 : 1;
    CHECK(s.iterations == 1);
    if (s.inside)
    {
      ++claimed;
      maxErr = std::max(maxErr, std::abs(double(s.value) - e.value(c)) / e.range());
    }
    converged10 += evaluateHex(v.data(), p, paramsFor(ElementTest::Bilinear)).converged ? 1 : 0;
  }
  CHECK(converged == 0);
  CHECK(outOfRange == 0);
  CHECK(converged10 == kPoints);
  MESSAGE("strongly twisted hex, 1 Newton iteration: claimed ",
    claimed,
    " of ",
    kPoints,
    " (max value error / range of claimed ",
    maxErr,
    "); with 10 iterations all converged");

  // An affine hex is solved exactly by the first update: not declared converged after one
  // iteration, but the residual test claims every inside point with the exact value.
  Element box = transformed(unitCell(Hex), affines()[5]);
  randomValues(rng, box);
  const auto vb = box.corners();
  const ForwardStats st = forwardTest(box, paramsFor(ElementTest::Bilinear, 1), 9u, true);
  CHECK(st.missed == 0);
  CHECK(st.falseHits == 0);
  CHECK(st.maxValueError <= kValueTolerance);
  const ElementSample s = evaluateHex(
    vb.data(), toFloat(box.map(dvec3(0.3, 0.6, 0.2))), paramsFor(ElementTest::Bilinear, 1));
  CHECK(s.inside);
  CHECK_FALSE(s.converged);
}

TEST_CASE("flat and invalid elements claim nothing and never give NaN")
{
  const glm::vec4 flatTet[4] = {
    { 0, 0, 0, 1 }, { 1, 0, 0, 2 }, { 0, 1, 0, 3 }, { 0.3f, 0.3f, 0, 4 }
  };
  const glm::vec4 thinTet[4] = {
    { 0, 0, 0, 1 }, { 1, 0, 0, 2 }, { 0, 1, 0, 3 }, { 0.3f, 0.3f, 1e-8f, 4 }
  };
  const glm::vec4 pointTet[4] = { { 5, 5, 5, 1 }, { 5, 5, 5, 2 }, { 5, 5, 5, 3 }, { 5, 5, 5, 4 } };
  float value = -1.0f;
  for (const glm::vec3 p : { glm::vec3(0.2f, 0.2f, 0.0f),
         glm::vec3(0.2f, 0.2f, 1e-9f),
         glm::vec3(0.3f, 0.3f, 0.0f),
         glm::vec3(5.0f) })
  {
    CHECK_FALSE(sampleTet(flatTet, p, value));
    CHECK_FALSE(sampleTet(thinTet, p, value));
    CHECK_FALSE(sampleTet(pointTet, p, value));
  }
  CHECK(value == -1.0f);

  // A thin but well-shaped tet (aspect 1e-4) is not flat.
  const glm::vec4 slab[4] = { { 0, 0, 0, 1 }, { 1, 0, 0, 2 }, { 0, 1, 0, 3 }, { 0, 0, 1e-4f, 4 } };
  CHECK(sampleTet(slab, glm::vec3(0.2f, 0.2f, 0.2e-4f), value));
  CHECK(std::abs(value - (1.0f + 0.2f + 0.4f + 0.6f)) < 1e-5f);

  // Flat pyramid / wedge / hex (all corners in z = 0) and a NaN point.
  const glm::vec4 flatHex[8] = { { 0, 0, 0, 1 },
    { 1, 0, 0, 2 },
    { 1, 1, 0, 3 },
    { 0, 1, 0, 4 },
    { 0, 0, 0, 5 },
    { 1, 0, 0, 6 },
    { 1, 1, 0, 7 },
    { 0, 1, 0, 8 } };
  const glm::vec4 flatPyr[5] = {
    { 0, 0, 0, 1 }, { 1, 0, 0, 2 }, { 1, 1, 0, 3 }, { 0, 1, 0, 4 }, { 0.5f, 0.5f, 0, 5 }
  };
  const glm::vec4 flatWedge[6] = {
    { 0, 0, 0, 1 }, { 1, 0, 0, 2 }, { 0, 1, 0, 3 }, { 0, 0, 0, 4 }, { 1, 0, 0, 5 }, { 0, 1, 0, 6 }
  };
  for (ElementTest test : { ElementTest::Bilinear, ElementTest::PlanarFaces })
  {
    const ElementTestParams prm = paramsFor(test);
    for (const glm::vec3 p : { glm::vec3(0.25f, 0.25f, 0.0f),
           glm::vec3(0.5f, 0.5f, 0.0f),
           glm::vec3(0.2f, 0.2f, 0.3f),
           glm::vec3(NAN, 0.5f, 0.5f) })
    {
      INFO(testName(test), " p = ", p.x, " ", p.y, " ", p.z);
      const ElementSample a = evaluateHex(flatHex, p, prm);
      const ElementSample b = evaluatePyramid(flatPyr, p, prm);
      const ElementSample c = evaluateWedge(flatWedge, p, prm);
      CHECK_FALSE(a.inside);
      CHECK_FALSE(b.inside);
      CHECK_FALSE(c.inside);
      CHECK(std::isfinite(a.value));
      CHECK(std::isfinite(b.value));
      CHECK(std::isfinite(c.value));
      CHECK_FALSE(sampleTet(flatTet, p, value));
    }
  }
}
