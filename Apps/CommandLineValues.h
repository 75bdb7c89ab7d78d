// The option table's building blocks for amrdm-render's command line (RenderCommandLine.cxx):
// an option row, and the parsers that turn an option's values into a setting with a clear error
// (integers and numbers with their ranges, number lists, flags), plus the rows and --help text
// of a parameter of the parameter table (core/ParameterTable.h): its option name, default,
// range and documentation all come from the table. CommandLineParser.h parses the rows (CLI11).
#pragma once

#include "core/ParameterTable.h"

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

namespace amrdm_app
{
namespace cli
{
using Values = std::vector<std::string>;
/// Applies one option's values; false + error on a bad value.
using Apply = std::function<bool(const Values&, std::string&)>;

/// One row of the option table: the name (CLI11 syntax; "-h,--help" gives two names to one
/// option), the value placeholders shown in --help (their count is the option's arity), the help
/// text (a '\n' continues it on the next line) and what the option sets.
struct Option
{
  std::string name;
  Values metavars;
  std::string help;
  Apply apply;
};

/// `v` as the shortest text that reads back (e.g. 0.25, 1e+30).
std::string shortNumber(double v);
/// The whole of `s` as a number.
bool toNumber(const std::string& s, double& out);
/// An integer in [lo, hi] into `out`.
Apply integer(int lo, int hi, int& out);
/// An integer with the table's range.
Apply integer(const amrdm::ParameterSpec& spec, int& out);
/// An integer with the table's range, handed to `set` (the generated rows: any integral field).
Apply integer(const amrdm::ParameterSpec& spec, std::function<void(int)> set);
/// A number with a check: `valid(d)` false gives "expected <what>".
Apply number(std::function<bool(double)> valid, std::string what, std::function<void(double)> set);
/// A number in the table's range.
Apply number(const amrdm::ParameterSpec& spec, std::function<void(double)> set);
/// As many numbers as the option has values (at most 4).
Apply numbers(std::function<void(const double*)> set);
/// As many numbers as the option has values (at most 4), each in the table's range.
Apply numbers(const amrdm::ParameterSpec& spec, std::function<void(const double*)> set);
/// The table's value into `field` (the generated rows of RenderCommandLine.cxx): Int rows as an
/// integer, Double rows as a number, Double3 rows as three numbers, each in the table's range
/// and converted to the field's type (float, std::uint32_t, glm::vec3, glm::ivec3, ...).
template<class T>
Apply into(const amrdm::ParameterSpec& spec, T& field)
{
  if (spec.type == amrdm::ParameterType::Int)
    return integer(spec, [&field](int v) { field = T(v); });
  if constexpr (!std::is_arithmetic_v<T>)
    if (spec.type == amrdm::ParameterType::Double3)
      return numbers(spec, [&field](const double* v) { field = T(v[0], v[1], v[2]); });
  return number(spec, [&field](double v) { field = T(v); });
}
/// An option without values.
Apply flag(std::function<void()> set);
/// --help text of a parameter from the table: its documentation, range and default (or
/// `defaultText`, e.g. the name an enum's default has on the command line), then `extra` (what
/// the option adds, e.g. the names of an enum).
std::string tableHelp(const amrdm::ParameterSpec& spec,
  const std::string& extra = "",
  const std::string& defaultText = "");
/// The row of a table parameter: the table's option name (spec.cliOption) and tableHelp().
Option tableOption(const amrdm::ParameterSpec& spec,
  Values metavars,
  Apply apply,
  const std::string& extra = "",
  const std::string& defaultText = "");

} // namespace cli
} // namespace amrdm_app
