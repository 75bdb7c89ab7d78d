// What the benchmark measures, and its JSON output (read by Benchmarks/report.py and plot.py).
// One Row per setting of one knob; one CurvePoint per progressive sample count (error against
// time); per-set facts (memory, counts, reference settings) as ready-made JSON objects.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace amrdm_bench
{

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Row
{
  std::string set, knob, setting, integrator; ///< integrator: "pt" or "rm"
  double msPerFrame = kNaN;                   ///< median wall time of one 1-spp frame
  int frames = 0;                             ///< frames accumulated (= spp of the measured image)
  double rmse = kNaN; ///< against the converged reference of the same integrator
  double psnr = kNaN;
  double p99 = kNaN, maxError = kNaN; ///< tail of |error| (ImageMetrics.h), same reference
  double rmseVsBaseline = kNaN;       ///< against the baseline setting, same seed and spp
  double bytes = kNaN;                ///< memory of the sampler / structure under test
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

/// A JSON number, null when not finite (6 significant digits, as the reports print).
inline nlohmann::ordered_json jsonValue(double v)
{
  return std::isfinite(v) ? nlohmann::ordered_json::parse(jsonNumber(v)) : nlohmann::ordered_json();
}

/// Any JSON value as text: escaped by nlohmann-json (quotes, backslashes, control characters),
/// ASCII only, bytes that are not UTF-8 replaced by U+FFFD.
inline std::string dumpJson(const nlohmann::ordered_json& j)
{
  return j.dump(-1, ' ', true, nlohmann::json::error_handler_t::replace);
}

/// A JSON string literal (for the per-set objects amrdm-bench composes).
inline std::string jsonString(const std::string& s)
{
  return dumpJson(nlohmann::ordered_json(s));
}

inline std::string toJson(const Row& r)
{
  nlohmann::ordered_json j;
  j["set"] = r.set;
  j["knob"] = r.knob;
  j["setting"] = r.setting;
  j["integrator"] = r.integrator;
  j["ms_per_frame"] = jsonValue(r.msPerFrame);
  j["frames"] = r.frames;
  j["rmse"] = jsonValue(r.rmse);
  j["psnr"] = jsonValue(r.psnr);
  j["p99"] = jsonValue(r.p99);
  j["max"] = jsonValue(r.maxError);
  j["rmse_vs_baseline"] = jsonValue(r.rmseVsBaseline);
  j["bytes"] = jsonValue(r.bytes);
  j["build_s"] = jsonValue(r.buildSeconds);
  j["baseline"] = r.baseline;
  return dumpJson(j);
}

inline std::string toJson(const CurvePoint& c)
{
  nlohmann::ordered_json j;
  j["set"] = c.set;
  j["knob"] = c.knob;
  j["setting"] = c.setting;
  j["integrator"] = c.integrator;
  j["spp"] = c.spp;
  j["seconds"] = jsonValue(c.seconds);
  j["rmse"] = jsonValue(c.rmse);
  return dumpJson(j);
}

template<typename T>
std::string jsonArray(const std::vector<T>& items)
{
  std::string s = "[";
  for (std::size_t i = 0; i < items.size(); ++i)
    s += (i ? ",\n  " : "\n  ") + toJson(items[i]);
  return s + "\n]";
}

} // namespace amrdm_bench
