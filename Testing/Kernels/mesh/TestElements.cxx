// Element tests (kernel only, no VTK), after OpenVKL's unstructured-volume sampling tests: unit
// cells of each type against analytic half-spaces and an analytic linear field, on scaled,
// translated, mirrored and sheared copies; twisted elements against the forward map; the
// PlanarFaces approximation measured on twisted cells. TestElementsDegenerate.cxx (the same
// executable) has the collapsed-corner hexes, the pyramid apex, the defined result when Newton
// does not converge and flat elements; the double-precision oracle is Support/DoubleElements.h.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "DoubleElements.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace amrdm;
using namespace amrdm_test;
using glm::dvec3;

TEST_CASE("unit cells and affine copies: half-space truth and exact linear field")
{
  for (const Affine& a : affines())
  {
    int bandTotal = 0;
    double maxErrTotal = 0.0;
    for (int k = kTet; k < kElementKindCount; ++k)
    {
      for (ElementTest test : { ElementTest::Bilinear, ElementTest::PlanarFaces })
      {
        if (k == kTet && test == ElementTest::PlanarFaces)
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
          const ElementSample s = evaluateElement(kind, v.data(), p, paramsFor(test));
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
    for (int k = kPyramid; k < kElementKindCount; ++k)
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
          std::string(elementKindName(k)),
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
  for (int k = kPyramid; k < kElementKindCount; ++k)
    planar.push_back(transformed(unitCell(Kind(k)), Affine{ "", shear, dvec3(3, -2, 1) }));
  Element skewApex = unitCell(kPyramid); // parallelogram base, apex anywhere above it
  skewApex.x[4] = dvec3(0.1, 0.9, 0.6);
  planar.push_back(transformed(skewApex, Affine{ "", shear, dvec3(0.0) }));
  Element frustum = unitCell(kWedge); // parallel triangles, top one shrunk: planar sides
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
  for (int k = kPyramid; k < kElementKindCount; ++k)
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
