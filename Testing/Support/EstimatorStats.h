// Statistics shared by the estimator tests: a running mean with its standard error, the
// "within kSigmas standard errors of the exact value" check, and the distance to a box's
// boundary for analytic transmittance.
#pragma once

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace estimator_stats
{
/// Statistical checks pass within this many standard errors.
constexpr double kSigmas = 3.0;
/// Absolute slack added to statistical bounds for estimators with (near) zero variance.
constexpr double kAbsSlack = 1e-6;

struct Stats
{
  double sum = 0.0, sumSq = 0.0;
  long long n = 0;
  void add(double x)
  {
    sum += x;
    sumSq += x * x;
    ++n;
  }
  double mean() const { return sum / double(n); }
  double variance() const
  {
    const double m = mean();
    return std::max(0.0, sumSq / double(n) - m * m) * double(n) / double(n - 1);
  }
  double stdError() const { return std::sqrt(variance() / double(n)); }
};

inline void checkWithin(const Stats& s, double exact, const std::string& what)
{
  const double err = std::fabs(s.mean() - exact);
  MESSAGE(what,
    ": estimate ",
    s.mean(),
    " +- ",
    s.stdError(),
    " (1 sigma), exact ",
    exact,
    ", |diff| = ",
    err / std::max(s.stdError(), 1e-300),
    " sigma");
  CHECK(err <= kSigmas * s.stdError() + kAbsSlack);
}

/// Distance from p along unit w to the boundary of box [lo, hi] (p inside).
inline double exitDistance(const glm::dvec3& p,
  const glm::dvec3& w,
  const glm::dvec3& lo,
  const glm::dvec3& hi)
{
  double t = 1e300;
  for (int a = 0; a < 3; ++a)
  {
    if (w[a] > 0)
      t = std::min(t, (hi[a] - p[a]) / w[a]);
    else if (w[a] < 0)
      t = std::min(t, (lo[a] - p[a]) / w[a]);
  }
  return t;
}
} // namespace estimator_stats
