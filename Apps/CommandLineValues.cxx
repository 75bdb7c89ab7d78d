#include "CommandLineValues.h"

#include <cstdlib>
#include <sstream>
#include <utility>

namespace amrdm_app
{
namespace cli
{
namespace
{
/// "a number in [lo, hi]", or "a number >= lo" when the table's maximum is DBL_MAX.
std::string rangeText(const amrdm::ParameterSpec& spec, const std::string& what)
{
  if (spec.maximum > 1e300)
    return what + " >= " + shortNumber(spec.minimum);
  return what + " in [" + shortNumber(spec.minimum) + ", " + shortNumber(spec.maximum) + "]";
}

bool inRange(const amrdm::ParameterSpec& spec, double d)
{
  return d >= spec.minimum && d <= spec.maximum;
}
}

std::string shortNumber(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

bool toNumber(const std::string& s, double& out)
{
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return !s.empty() && end && !*end;
}

/// Each parser returns an apply function for one option's values.
Apply integer(int lo, int hi, int& out)
{
  return [lo, hi, &out](const Values& v, std::string& error)
  {
    double d;
    if (!toNumber(v[0], d) || d != double(long(d)) || d < lo || d > hi)
    {
      error = "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
              "], got '" + v[0] + "'";
      return false;
    }
    out = int(d);
    return true;
  };
}

Apply integer(const amrdm::ParameterSpec& spec, int& out)
{
  return integer(int(spec.minimum), int(spec.maximum), out);
}

Apply integer(const amrdm::ParameterSpec& spec, std::function<void(int)> set)
{
  return [&spec, set = std::move(set)](const Values& v, std::string& error)
  {
    int n = 0;
    if (!integer(spec, n)(v, error))
      return false;
    set(n);
    return true;
  };
}

Apply number(std::function<bool(double)> valid, std::string what, std::function<void(double)> set)
{
  return [valid = std::move(valid), what = std::move(what), set = std::move(set)](
           const Values& v, std::string& error)
  {
    double d;
    if (!toNumber(v[0], d) || !valid(d))
    {
      error = "expected " + what + ", got '" + v[0] + "'";
      return false;
    }
    set(d);
    return true;
  };
}

Apply number(const amrdm::ParameterSpec& spec, std::function<void(double)> set)
{
  return number(
    [&spec](double d) { return inRange(spec, d); }, rangeText(spec, "a number"), std::move(set));
}

Apply numbers(std::function<void(const double*)> set)
{
  return [set = std::move(set)](const Values& v, std::string& error)
  {
    double d[4];
    for (std::size_t k = 0; k < v.size(); ++k)
    {
      if (!toNumber(v[k], d[k]))
      {
        error = "expected " + std::to_string(v.size()) + " numbers, got '" + v[k] + "'";
        return false;
      }
    }
    set(d);
    return true;
  };
}

Apply numbers(const amrdm::ParameterSpec& spec, std::function<void(const double*)> set)
{
  return [&spec, set = std::move(set)](const Values& v, std::string& error)
  {
    double d[4];
    for (std::size_t k = 0; k < v.size(); ++k)
    {
      if (!toNumber(v[k], d[k]) || !inRange(spec, d[k]))
      {
        error = "expected " + std::to_string(v.size()) + " " + rangeText(spec, "numbers") +
                ", got '" + v[k] + "'";
        return false;
      }
    }
    set(d);
    return true;
  };
}

Apply flag(std::function<void()> set)
{
  return [set = std::move(set)](const Values&, std::string&)
  {
    set();
    return true;
  };
}

std::string tableHelp(const amrdm::ParameterSpec& spec,
  const std::string& extra,
  const std::string& defaultText)
{
  std::string range;
  if (spec.type != amrdm::ParameterType::Enum && spec.maximum < 1e300 &&
      spec.minimum > -2147483648.0)
    range = "; " + shortNumber(spec.minimum) + ".." + shortNumber(spec.maximum);
  std::string def = shortNumber(spec.defaultValue);
  if (spec.type == amrdm::ParameterType::Double3)
    def = def + " " + def + " " + def;
  if (!defaultText.empty())
    def = defaultText;
  return std::string(spec.doc) + range + " (default " + def + ")" +
         (extra.empty() ? "" : "\n" + extra);
}

Option tableOption(const amrdm::ParameterSpec& spec,
  Values metavars,
  Apply apply,
  const std::string& extra,
  const std::string& defaultText)
{
  return {
    spec.cliOption, std::move(metavars), tableHelp(spec, extra, defaultText), std::move(apply)
  };
}

} // namespace cli
} // namespace amrdm_app
