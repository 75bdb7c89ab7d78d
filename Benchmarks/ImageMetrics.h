// Image error metrics of the benchmark, on linear HDR values: premultiplied RGB, i.e. the image
// composited over a black background (the alpha channel is left out so that 8-bit RGB captures
// from ParaView compare the same way). PSNR uses a peak of 1.0 (the transfer function's colours
// are in [0, 1]; path-traced radiance can exceed it).
#pragma once

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

/// PSNR in dB for a peak of 1.0 (infinite for identical images).
inline double psnr(double rmse)
{
  return rmse > 0.0 ? -20.0 * std::log10(rmse) : std::numeric_limits<double>::infinity();
}

} // namespace amrdm_bench
