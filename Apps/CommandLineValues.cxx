#include "CommandLineValues.h"

#include <cstdlib>
#include <sstream>

namespace amrdm_app
{
namespace cli
{

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

/// A number with a check: `valid(d)` false gives "expected <what>".
Apply number(std::function<bool(double)> valid, std::string what, std::function<void(double)> set)
{
  return [valid, what, set](const Values& v, std::string& error)
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

Apply numbers(std::function<void(const double*)> set)
{
  return [set](const Values& v, std::string& error)
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

Apply flag(std::function<void()> set)
{
  return [set](const Values&, std::string&)
  {
    set();
    return true;
  };
}

/// --help text of a parameter from the table (core/ParameterTable.h): its documentation, range
/// and default, then `extra` (what the option adds, e.g. the names of an enum).
std::string tableHelp(const amrdm::ParameterSpec& spec, const std::string& extra)
{
  std::string range;
  if (spec.type != amrdm::ParameterType::Enum && spec.maximum < 1e300 &&
      spec.minimum > -2147483648.0)
    range = "; " + shortNumber(spec.minimum) + ".." + shortNumber(spec.maximum);
  std::string def = shortNumber(spec.defaultValue);
  if (spec.type == amrdm::ParameterType::Double3)
    def = def + " " + def + " " + def;
  return std::string(spec.doc) + range + " (default " + def + ")" +
         (extra.empty() ? "" : "\n" + extra);
}

/// An integer option with the table's range.
Apply integer(const amrdm::ParameterSpec& spec, int& out)
{
  return integer(int(spec.minimum), int(spec.maximum), out);
}

} // namespace cli
} // namespace amrdm_app
