// What the benchmark measures, and its JSON output (read by Benchmarks/report.py and plot.py).
// One Row per setting of one knob; one CurvePoint per progressive sample count (error against
// time); per-set facts (memory, counts, reference settings) as ready-made JSON objects.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace amrdm_bench
{

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Row
{
  std::string set, knob, setting, integrator; ///< integrator: "pt" or "rm"
  double msPerFrame = kNaN;  ///< median wall time of one 1-spp frame
  int frames = 0;            ///< frames accumulated (= spp of the measured image)
  double rmse = kNaN;        ///< against the converged reference of the same integrator
  double psnr = kNaN;
  double rmseVsBaseline = kNaN; ///< against the baseline setting, same seed and spp
  double bytes = kNaN;       ///< memory of the sampler / structure under test
  double buildSeconds = kNaN;
  bool baseline = false;
};

struct CurvePoint
{
  std::string set, knob, setting, integrator;
  int spp = 0;
  double seconds = 0.0; ///< cumulative render time up to this sample count
  double rmse = kNaN;
};

inline std::string jsonNumber(double v)
{
  if (!std::isfinite(v))
    return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

inline std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

inline std::string toJson(const Row& r)
{
  std::ostringstream o;
  o << "{\"set\": " << jsonString(r.set) << ", \"knob\": " << jsonString(r.knob)
    << ", \"setting\": " << jsonString(r.setting) << ", \"integrator\": " << jsonString(r.integrator)
    << ", \"ms_per_frame\": " << jsonNumber(r.msPerFrame) << ", \"frames\": " << r.frames
    << ", \"rmse\": " << jsonNumber(r.rmse) << ", \"psnr\": " << jsonNumber(r.psnr)
    << ", \"rmse_vs_baseline\": " << jsonNumber(r.rmseVsBaseline)
    << ", \"bytes\": " << jsonNumber(r.bytes) << ", \"build_s\": " << jsonNumber(r.buildSeconds)
    << ", \"baseline\": " << (r.baseline ? "true" : "false") << "}";
  return o.str();
}

inline std::string toJson(const CurvePoint& c)
{
  std::ostringstream o;
  o << "{\"set\": " << jsonString(c.set) << ", \"knob\": " << jsonString(c.knob)
    << ", \"setting\": " << jsonString(c.setting) << ", \"integrator\": " << jsonString(c.integrator)
    << ", \"spp\": " << c.spp << ", \"seconds\": " << jsonNumber(c.seconds)
    << ", \"rmse\": " << jsonNumber(c.rmse) << "}";
  return o.str();
}

template <typename T>
std::string jsonArray(const std::vector<T>& items)
{
  std::string s = "[";
  for (std::size_t i = 0; i < items.size(); ++i)
    s += (i ? ",\n  " : "\n  ") + toJson(items[i]);
  return s + "\n]";
}

} // namespace amrdm_bench
