// Statistical image comparison, after Mitsuba 3's image tests: do two renders estimate the same
// image? Each image is a mean and a variance of the mean per pixel and channel (with the degrees
// of freedom of that variance). Overall significance `alpha` (the chance that two unbiased
// estimates of one image are told apart), split evenly between two criteria:
// 1. Per pixel and channel, Welch's t-test, t = (mean_a - mean_b) / sqrt(v_a + v_b),
//    Welch-Satterthwaite dof, two-sided Student p; Sidak over all N tests: reject when
//    p < 1 - (1 - alpha/2)^(1/N). v_a is floored at b's per-sample variance over a's sample count
//    (under H0 both draw the same per-sample distribution; unfloored, a pixel whose samples all
//    missed a rare region has v_a = 0). Catches local errors.
// 2. Per channel, the summed difference z = sum(mean_a - mean_b) / sqrt(sum(v_a + v_b)), Sidak
//    over the 4 channels at alpha/2. Catches small global biases no single pixel resolves.
// Pairs with both variances zero pass only when the means agree. Used by
// TestPathTracerStatistics (render against a stored reference) and amrdm-devcheck (CPU against
// CUDA). Host code.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace amrdm
{

/// Continued fraction of the regularised incomplete beta function (modified Lentz method);
/// converges quickly for x < (a + 1) / (a + b + 2).
inline double betaContinuedFraction(double a, double b, double x)
{
  auto guard = [](double v) { return std::fabs(v) < 1e-300 ? 1e-300 : v; };
  double c = 1.0, d = 1.0 / guard(1.0 - (a + b) * x / (a + 1.0)), f = d;
  for (int m = 1; m <= 1000; ++m)
  {
    // Terms 2m and 2m + 1: m (b - m) x / ((a + 2m - 1)(a + 2m)) and
    // -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)).
    const double coeffs[2] = { m * (b - m) * x / ((a + 2.0 * m - 1.0) * (a + 2.0 * m)),
      -(a + m) * (a + b + m) * x / ((a + 2.0 * m) * (a + 2.0 * m + 1.0)) };
    double delta = 1.0;
    for (double coeff : coeffs)
    {
      d = 1.0 / guard(1.0 + coeff * d);
      c = guard(1.0 + coeff / c);
      delta = c * d;
      f *= delta;
    }
    if (std::fabs(delta - 1.0) < 1e-15)
      break;
  }
  return f;
}

/// Regularised incomplete beta function I_x(a, b), a, b > 0, x in [0, 1].
inline double incompleteBeta(double a, double b, double x)
{
  if (x <= 0.0 || x >= 1.0)
    return x <= 0.0 ? 0.0 : 1.0;
  const double logFront =
    std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0))
    return std::exp(logFront) * betaContinuedFraction(a, b, x) / a;
  return 1.0 - std::exp(logFront) * betaContinuedFraction(b, a, 1.0 - x) / b;
}

/// Two-sided p-value P(|T| >= |t|) of Student's t with `dof` > 0 (real) degrees of freedom:
/// I_{dof / (dof + t^2)}(dof / 2, 1 / 2), accurate far into the tail.
inline double studentTwoSidedP(double t, double dof)
{
  return incompleteBeta(0.5 * dof, 0.5, dof / (dof + t * t));
}

/// Per-test level of a Sidak correction: `tests` tests at family-wise level `alpha`.
inline double sidak(double alpha, double tests)
{
  return -std::expm1(std::log1p(-alpha) / tests);
}

/// Per pixel and channel (RGBA): mean and variance of the mean, with the degrees of freedom of
/// that variance and the samples per pixel.
struct ImageEstimate
{
  std::vector<double> mean, var;
  double dof = 0.0;
  int spp = 0;
};

struct ImageVerdict
{
  std::size_t tests = 0, rejectedTests = 0, rejectedPixels = 0, empty = 0;
  double pixelThreshold = 0.0, imageThreshold = 0.0; ///< per-test levels (Sidak)
  double minP = 1.0;                                 ///< smallest per-pixel p
  double below1Percent = 0.0; ///< fraction of non-empty tests with p < 0.01 (~0.01 or less)
  double imageZ[4] = {}, imageP[4] = {};
  int rejectedChannels = 0;
  std::vector<float> p; ///< per pixel and channel
  bool rejected() const { return this->rejectedPixels > 0 || this->rejectedChannels > 0; }
};

/// Both criteria at overall level `alpha` (see the top of this file); `test` and `ref` must have
/// the same size (4 values per pixel) and dof >= 1.
inline ImageVerdict compareImages(const ImageEstimate& test, const ImageEstimate& ref, double alpha)
{
  ImageVerdict v;
  v.tests = std::min(test.mean.size(), ref.mean.size());
  v.pixelThreshold = sidak(0.5 * alpha, double(std::max<std::size_t>(1, v.tests)));
  v.imageThreshold = sidak(0.5 * alpha, 4.0);
  v.p.assign(v.tests, 1.0f);
  double sumDiff[4] = {}, sumVar[4] = {};
  std::size_t below = 0;
  for (std::size_t i = 0; i + 4 <= v.tests; i += 4)
  {
    bool pixelRejected = false;
    for (std::size_t k = i; k < i + 4; ++k)
    {
      const double diff = test.mean[k] - ref.mean[k];
      sumDiff[k % 4] += diff;
      sumVar[k % 4] += test.var[k] + ref.var[k];
      const double vr = ref.var[k], vtFloor = vr * ref.spp / std::max(1, test.spp);
      const bool floored = test.var[k] < vtFloor;
      const double vt = floored ? vtFloor : test.var[k], vsum = vt + vr;
      // Floored, both variance terms come from the reference: its degrees of freedom.
      const double dof = floored ? ref.dof : vsum * vsum / (vt * vt / test.dof + vr * vr / ref.dof);
      const bool empty = !(vsum > 0.0); // then only equal means pass
      const double p = empty ? (std::fabs(diff) <= 1e-6 * std::fabs(ref.mean[k]) ? 1.0 : 0.0)
                             : studentTwoSidedP(diff / std::sqrt(vsum), dof);
      v.empty += empty;
      below += !empty && p < 0.01;
      v.p[k] = float(p);
      v.minP = std::min(v.minP, p);
      v.rejectedTests += p < v.pixelThreshold;
      pixelRejected = pixelRejected || p < v.pixelThreshold;
    }
    v.rejectedPixels += pixelRejected;
  }
  v.below1Percent = double(below) / double(std::max<std::size_t>(1, v.tests - v.empty));
  for (int c = 0; c < 4; ++c)
  {
    v.imageZ[c] = sumVar[c] > 0.0 ? sumDiff[c] / std::sqrt(sumVar[c]) : 0.0;
    v.imageP[c] = std::erfc(std::fabs(v.imageZ[c]) / std::sqrt(2.0));
    v.rejectedChannels += v.imageP[c] < v.imageThreshold;
  }
  return v;
}

} // namespace amrdm
