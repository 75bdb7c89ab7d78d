// Element tests, degenerate cases (part of the TestElements executable, see TestElements.cxx):
// hexes with collapsed corners, the pyramid apex neighbourhood, the defined result when Newton
// does not converge, and flat or invalid elements (nothing claimed, never NaN).
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
    Element e = unitCell(kHex);
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
  Element e = twistedCell(kPyramid);
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
    const dvec3 c = randomPcoords(rng, kHex, 0.0);
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
  Element box = transformed(unitCell(kHex), affines()[5]);
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
