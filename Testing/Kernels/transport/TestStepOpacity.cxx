// The ray marcher's per-step opacity (transport/RayMarcher.h, stepOpacity): 1 - (1 - alpha)^e
// against the same formula in long double, over table opacities from 1e-9 to the table's cap
// and exponents from 1e-7 (a tiny step or density scale) to 1e3, both sides of the series'
// switch points; the relative error stays below 1e-5, the value in [0, 1], monotone in both.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "transport/RayMarcher.h"

#include <cmath>
#include <vector>

using namespace amrdm;

namespace
{
long double exact(float alpha, float exponent)
{
  return -std::expm1((long double)exponent * std::log1p(-(long double)alpha));
}

std::vector<float> logRange(float lo, float hi, int perDecade)
{
  std::vector<float> v;
  const int n = int(std::round(std::log10(hi / lo) * perDecade));
  for (int i = 0; i <= n; ++i)
  {
    v.push_back(float(lo * std::pow(10.0, double(i) / perDecade)));
  }
  return v;
}
}

TEST_CASE("stepOpacity: 1 - (1 - alpha)^e to a relative error below 1e-5")
{
  std::vector<float> alphas = logRange(1e-9f, 0.5f, 40);
  for (float a : { 0.03125f, std::nextafter(0.03125f, 0.0f), 0.6f, 0.9f, 0.99f, kMaxTableOpacity })
  {
    alphas.push_back(a);
  }
  std::vector<float> exponents = logRange(1e-7f, 1e3f, 20);
  double worst = 0.0;
  for (float a : alphas)
  {
    for (float e : exponents)
    {
      const long double want = exact(a, e);
      const float got = stepOpacity(a, e);
      REQUIRE(got >= 0.0f);
      REQUIRE(got <= 1.0f);
      const double rel = double(std::fabs((long double)got - want) / want);
      worst = std::max(worst, rel);
      INFO("alpha " << a << ", exponent " << e << ": " << got << " against " << double(want));
      CHECK(rel < 1e-5);
    }
  }
  MESSAGE("largest relative error " << worst);
  CHECK(stepOpacity(0.0f, 1.0f) == 0.0f);
  CHECK(stepOpacity(0.5f, 0.0f) == 0.0f);
  CHECK(stepOpacity(0.5f, 1.0f) == doctest::Approx(0.5f).epsilon(1e-6));
  // The switch at x = -1/32 between the series and 1 - exp(x) is continuous.
  const float e = 0.03125f / 0.5f; // alpha 0.5 above the log switch: x = e ln(0.5)
  for (float d : { 0.999f, 1.0f, 1.001f })
  {
    const double want = double(exact(0.5f, e * d));
    CHECK(std::fabs(stepOpacity(0.5f, e * d) - want) / want < 1e-5);
  }
}

TEST_CASE("stepOpacity is monotone in alpha and in the exponent")
{
  float previous = -1.0f;
  for (float a : logRange(1e-6f, 0.9f, 200))
  {
    const float v = stepOpacity(a, 0.37f);
    CHECK(v >= previous);
    previous = v;
  }
  previous = -1.0f;
  for (float e : logRange(1e-4f, 10.0f, 200))
  {
    const float v = stepOpacity(0.2f, e);
    CHECK(v >= previous);
    previous = v;
  }
}
