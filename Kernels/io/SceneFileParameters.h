// The parameter table's section of a scene file (SceneFile.cpp): every row the file stores
// (core/ParameterTable.h, all but NotInSceneFile) by its name, in the table's units, so that a new
// row needs no hand-written field and no new file version: a file without a row reads its
// default, a value outside the row's range or a name this build does not know is refused naming
// it. Layout (little-endian): u32 count, then per row u32 name length, name bytes, u8 components
// (1, or 3 for a vector field), f64 value[components]. f64 holds every int32 and float exactly.
// Host code.
#pragma once

#include "core/ParameterTable.h"
#include "io/SceneFileCodec.h"

#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <limits>
#include <string>
#include <type_traits>

namespace amrdm
{
namespace scenefile
{

/// A kernel field's components in the table's units (the value the mapper's Set takes).
template<typename T>
int tableValue(const T& field, double* v)
{
  static_assert(std::is_arithmetic<T>::value || std::is_enum<T>::value,
    "a scene-file parameter is a number, an enumeration, a glm::vec3 or a glm::ivec3");
  if constexpr (std::is_enum<T>::value)
    v[0] = double(int(field));
  else if constexpr (std::is_same<T, std::uint32_t>::value)
    v[0] = double(std::int32_t(field)); // the seed: the table's int, as the mapper casts it
  else
    v[0] = double(field);
  return 1;
}
inline int tableValue(const glm::vec3& field, double* v)
{
  for (int a = 0; a < 3; ++a)
    v[a] = double(field[a]);
  return 3;
}
inline int tableValue(const glm::ivec3& field, double* v)
{
  for (int a = 0; a < 3; ++a)
    v[a] = double(field[a]);
  return 3;
}

/// The type of one component of a kernel field in the table's units: an enumeration and the
/// (unsigned) seed are the table's int, a glm vector its component type.
template<typename T>
struct TableScalar
{
  using type =
    std::conditional_t<std::is_enum<T>::value || std::is_same<T, std::uint32_t>::value, int, T>;
};
template<>
struct TableScalar<glm::vec3>
{
  using type = float;
};
template<>
struct TableScalar<glm::ivec3>
{
  using type = int;
};

/// The bound `b` of a row as a component of type S holds it: a float field holds float(0.99),
/// which is above the double 0.99; a bound beyond the type's range is that range.
template<typename S>
double fieldBound(double b)
{
  if (std::is_integral<S>::value)
    return std::min(std::max(b, double(INT32_MIN)), double(INT32_MAX));
  if (b >= double(FLT_MAX))
    return std::numeric_limits<double>::infinity();
  if (b <= -double(FLT_MAX))
    return -std::numeric_limits<double>::infinity();
  return double(float(b));
}

/// The `components` values `v` of row `spec` into `field`; false when one is outside the row's
/// range, not a number, or not an integer for an integer field.
template<typename T>
bool setTableValue(const ParameterSpec& spec, const double* v, int components, T& field)
{
  using S = typename TableScalar<T>::type;
  for (int a = 0; a < components; ++a)
  {
    if (!(v[a] >= fieldBound<S>(spec.minimum) && v[a] <= fieldBound<S>(spec.maximum)) ||
        (std::is_integral<S>::value && v[a] != double(std::int64_t(v[a]))))
      return false;
  }
  if constexpr (std::is_same<T, glm::vec3>::value || std::is_same<T, glm::ivec3>::value)
  {
    for (int a = 0; a < 3; ++a)
      field[a] = S(v[a]);
  }
  else
  {
    field = T(S(v[0])); // the seed: uint32(int), as the mapper casts it
  }
  return true;
}

/// `v` as a message shows it: 17, 0.99, 1.79769313e+308.
inline std::string number(double v)
{
  std::ostringstream out;
  out << std::setprecision(9) << v;
  return out.str();
}

/// Calls visit(spec, field) for every row `s` stores (SceneFile.cpp's generated block).
template<typename Scene, typename Visit>
void visitSceneParameters(Scene& s, Visit&& visit);

/// Writes the rows of `s` (see the layout above).
template<typename Scene>
void writeSceneParameters(Writer& w, const Scene& s)
{
  Writer rows;
  std::uint32_t count = 0;
  visitSceneParameters(s,
    [&](const ParameterSpec& spec, const auto& field)
    {
      double v[3];
      const int n = tableValue(field, v);
      const std::string name = spec.name;
      rows.u32(std::uint32_t(name.size()));
      rows.bytes.insert(rows.bytes.end(), name.begin(), name.end());
      rows.u8(std::uint8_t(n));
      for (int a = 0; a < n; ++a)
        rows.f64(v[a]);
      ++count;
    });
  w.u32(count);
  w.bytes.insert(w.bytes.end(), rows.bytes.begin(), rows.bytes.end());
}

/// Reads the rows into `s` (the rows a file lacks keep their defaults); fails naming a row that
/// is unknown, repeated, of the wrong size or out of range.
template<typename Scene>
void readSceneParameters(Reader& r, Scene& s)
{
  constexpr std::uint32_t kMaxNameBytes = 256;
  const std::uint32_t count = r.u32("the number of table parameters");
  const std::uint32_t rows = std::uint32_t(sizeof(kParameters) / sizeof(kParameters[0]));
  if (count > rows)
    r.fail(std::to_string(count) + " table parameters; expected at most " + std::to_string(rows));
  std::string seen = ",";
  for (std::uint32_t i = 0; i < count; ++i)
  {
    const std::uint32_t length = r.u32("a parameter name's length");
    if (length < 1 || length > kMaxNameBytes)
      r.fail("a parameter name of " + std::to_string(length) + " bytes; expected 1.." +
             std::to_string(kMaxNameBytes));
    std::string name;
    r.need(length, "a parameter name");
    for (std::uint32_t c = 0; c < length; ++c)
      name.push_back(char(r.u8("a parameter name")));
    const int n = r.u8("a parameter's number of components");
    if (n != 1 && n != 3)
      r.fail(name + " has " + std::to_string(n) + " components; expected 1 or 3");
    double v[3];
    for (int a = 0; a < n; ++a)
      v[a] = r.f64("a parameter value");
    if (seen.find("," + name + ",") != std::string::npos)
      r.fail(name + " is stored twice; expected each parameter once");
    seen += name + ",";
    bool known = false;
    visitSceneParameters(s,
      [&](const ParameterSpec& spec, auto& field)
      {
        if (name != spec.name)
          return;
        known = true;
        double current[3];
        if (tableValue(field, current) != n)
          r.fail(name + " has " + std::to_string(n) + " components; expected " +
                 std::to_string(tableValue(field, current)));
        if (!setTableValue(spec, v, n, field))
        {
          std::string value;
          for (int a = 0; a < n; ++a)
            value += (a ? " " : "") + number(v[a]);
          const bool real =
            spec.type == ParameterType::Double || spec.type == ParameterType::Double3;
          r.fail(name + " is " + value + "; expected " + (real ? "a number" : "an integer") +
                 " in " + number(spec.minimum) + ".." + number(spec.maximum));
        }
      });
    if (!known)
      r.fail("unknown parameter '" + name +
             "' (a file of a newer build?); expected the rows of "
             "core/ParameterTable.h this build stores");
  }
}

} // namespace scenefile
} // namespace amrdm
