#include "TransferFunctionPresets.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace amrdm_app
{
namespace
{
constexpr int kTableSize = 256;

struct ControlPoint
{
  double x;
  glm::vec3 rgb;
};

/// Colour maps as control points on [0, 1] (linear RGB), interpolated linearly.
bool presetColors(const std::string& name, std::vector<ControlPoint>& points)
{
  if (name == "cool-warm") // after Moreland's diverging map
    points = { { 0.0, { 0.230, 0.299, 0.754 } },
      { 0.5, { 0.865, 0.865, 0.865 } },
      { 1.0, { 0.706, 0.016, 0.150 } } };
  else if (name == "viridis")
    points = { { 0.0, { 0.267, 0.005, 0.329 } },
      { 0.25, { 0.229, 0.322, 0.546 } },
      { 0.5, { 0.128, 0.567, 0.551 } },
      { 0.75, { 0.369, 0.789, 0.383 } },
      { 1.0, { 0.993, 0.906, 0.144 } } };
  else if (name == "inferno")
    points = { { 0.0, { 0.001, 0.000, 0.014 } },
      { 0.25, { 0.341, 0.062, 0.429 } },
      { 0.5, { 0.735, 0.216, 0.330 } },
      { 0.75, { 0.978, 0.557, 0.035 } },
      { 1.0, { 0.988, 0.998, 0.645 } } };
  else if (name == "grayscale")
    points = { { 0.0, { 0.0, 0.0, 0.0 } }, { 1.0, { 1.0, 1.0, 1.0 } } };
  else if (name == "white") // constant white albedo: shape by lighting only
    points = { { 0.0, { 1.0, 1.0, 1.0 } }, { 1.0, { 1.0, 1.0, 1.0 } } };
  else
    return false;
  return true;
}

glm::vec3 interpolate(const std::vector<ControlPoint>& points, double x)
{
  if (x <= points.front().x)
    return points.front().rgb;
  for (std::size_t i = 1; i < points.size(); ++i)
  {
    if (x <= points[i].x)
    {
      const double f = (x - points[i - 1].x) / (points[i].x - points[i - 1].x);
      return points[i - 1].rgb + float(f) * (points[i].rgb - points[i - 1].rgb);
    }
  }
  return points.back().rgb;
}
}

const char* PresetNames()
{
  return "cool-warm, viridis, inferno, grayscale, white";
}

bool IsPreset(const std::string& spec)
{
  std::vector<ControlPoint> colors;
  return presetColors(spec, colors);
}

bool MakeTransferFunction(const std::string& spec,
  double lo,
  double hi,
  double maxOpacity,
  double unitDistance,
  amrdm::TransferFunction& tf,
  std::string& error,
  const std::vector<float>& opacityWeights)
{
  tf = amrdm::TransferFunction();
  tf.unitDistance = static_cast<float>(unitDistance);
  tf.table.resize(kTableSize);
  std::vector<ControlPoint> colors;
  if (presetColors(spec, colors))
  {
    tf.lo = static_cast<float>(lo);
    tf.hi = static_cast<float>(hi);
    for (int i = 0; i < kTableSize; ++i)
    {
      const double x = double(i) / (kTableSize - 1);
      const float weight = opacityWeights.empty()
                             ? 1.0f
                             : opacityWeights[std::min(opacityWeights.size() - 1,
                                 std::size_t(x * double(opacityWeights.size())))];
      tf.table[i] = glm::vec4(interpolate(colors, x), float(maxOpacity * x) * weight);
    }
    return true;
  }
  std::ifstream file(spec);
  if (!file)
  {
    error = "unknown transfer function '" + spec + "'; expected a preset (" + PresetNames() +
            ") or a file of 'value r g b a' lines";
    return false;
  }
  std::vector<std::pair<double, glm::vec4>> points;
  std::string line;
  int lineNo = 0;
  while (std::getline(file, line))
  {
    ++lineNo;
    line = line.substr(0, line.find('#'));
    std::istringstream in(line);
    double v, r, g, b, a;
    if (!(in >> v))
      continue;
    if (!(in >> r >> g >> b >> a) || r < 0 || g < 0 || b < 0 || a < 0 || a > 1)
    {
      error = spec + ":" + std::to_string(lineNo) +
              ": expected 'value r g b a' with colours >= 0 and opacity in [0, 1]";
      return false;
    }
    points.push_back({ v, glm::vec4(r, g, b, a) });
  }
  if (points.size() < 2 || !std::is_sorted(points.begin(),
                             points.end(),
                             [](const auto& p, const auto& q) { return p.first < q.first; }))
  {
    error = spec + ": expected at least two control points with increasing values";
    return false;
  }
  tf.lo = static_cast<float>(points.front().first);
  tf.hi = static_cast<float>(points.back().first);
  for (int i = 0; i < kTableSize; ++i)
  {
    const double v = tf.lo + (tf.hi - tf.lo) * double(i) / (kTableSize - 1);
    std::size_t k = 1;
    while (k + 1 < points.size() && points[k].first < v)
      ++k;
    const double f =
      std::clamp((v - points[k - 1].first) / (points[k].first - points[k - 1].first), 0.0, 1.0);
    tf.table[i] = points[k - 1].second + float(f) * (points[k].second - points[k - 1].second);
  }
  return true;
}
}
