// Image error metrics of the benchmark, on linear HDR values: premultiplied RGB, i.e. the image
// composited over a black background (the alpha channel is left out so that 8-bit RGB captures
// from ParaView compare the same way). PSNR uses a peak of 1.0 (the transfer function's colours
// are in [0, 1]; path-traced radiance can exceed it).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace amrdm_bench
{

/// Root mean square error over the R, G, B channels of two RGBA images of equal size.
inline double rmseRGB(const std::vector<float>& a, const std::vector<float>& b)
{
  const std::size_t n = std::min(a.size(), b.size()) / 4;
  if (n == 0)
    return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
    {
      const double d = double(a[4 * i + c]) - double(b[4 * i + c]);
      s += d * d;
    }
  return std::sqrt(s / double(3 * n));
}

/// The 99th percentile and the maximum of |a - b| over the R, G, B channels (the tail the RMSE
/// averages away: a thin feature missed, a seam). {NaN, NaN} for empty images.
struct TailErrors
{
  double p99 = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
};

inline TailErrors tailErrorsRGB(const std::vector<float>& a, const std::vector<float>& b)
{
  const std::size_t n = std::min(a.size(), b.size()) / 4;
  TailErrors t;
  if (n == 0)
    return t;
  std::vector<double> d;
  d.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      d.push_back(std::abs(double(a[4 * i + c]) - double(b[4 * i + c])));
  const std::size_t k = std::min(d.size() - 1, std::size_t(0.99 * double(d.size() - 1) + 0.5));
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(k), d.end());
  t.p99 = d[k];
  t.max = *std::max_element(d.begin() + std::ptrdiff_t(k), d.end());
  return t;
}

/// PSNR in dB for a peak of 1.0 (infinite for identical images).
inline double psnr(double rmse)
{
  return rmse > 0.0 ? -20.0 * std::log10(rmse) : std::numeric_limits<double>::infinity();
}

} // namespace amrdm_bench
