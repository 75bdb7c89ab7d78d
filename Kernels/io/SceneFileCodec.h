// Little-endian byte codec of scene files (SceneFile.cpp): Writer appends u8/u32/i32/u64/f32/f64
// values and vectors; Reader takes them back and throws SceneFileError, naming the field, when
// the bytes run out. Host code, internal to the scene-file implementation.
#pragma once

#include "io/SceneFile.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace amrdm
{
namespace scenefile
{

class Writer
{
public:
  std::vector<std::uint8_t> bytes;

  void u8(std::uint8_t v) { this->bytes.push_back(v); }
  /// An unsigned integer, its sizeof(T) bytes lowest first.
  template<typename T>
  void uintLE(T v)
  {
    for (std::size_t i = 0; i < sizeof(T); ++i)
      this->bytes.push_back(std::uint8_t(v >> (8 * i)));
  }
  void u32(std::uint32_t v) { this->uintLE(v); }
  void u64(std::uint64_t v) { this->uintLE(v); }
  void i32(std::int32_t v) { this->u32(std::uint32_t(v)); }
  void f32(float v)
  {
    std::uint32_t u;
    std::memcpy(&u, &v, 4);
    this->u32(u);
  }
  void f64(double v)
  {
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    this->u64(u);
  }
  void vec3(const glm::vec3& v)
  {
    for (int a = 0; a < 3; ++a)
      this->f32(v[a]);
  }
  void dvec3(const glm::dvec3& v)
  {
    for (int a = 0; a < 3; ++a)
      this->f64(v[a]);
  }
  void ivec3(const glm::ivec3& v)
  {
    for (int a = 0; a < 3; ++a)
      this->i32(v[a]);
  }
};

class Reader
{
public:
  Reader(const std::vector<std::uint8_t>& bytes, std::size_t begin, const std::string& what)
    : Bytes(bytes)
    , Pos(begin)
    , What(what)
  {
  }

  std::uint64_t left() const { return this->Bytes.size() - this->Pos; }
  std::size_t position() const { return this->Pos; }
  [[noreturn]] void fail(const std::string& message) const
  {
    throw SceneFileError(this->What + ": " + message + " (at byte " + std::to_string(this->Pos) +
                         " of " + std::to_string(this->Bytes.size()) + ")");
  }
  /// Fails unless `n` more bytes exist for `field`.
  void need(std::uint64_t n, const std::string& field) const
  {
    if (n > this->left())
    {
      this->fail("truncated: " + field + " needs " + std::to_string(n) + " bytes, only " +
                 std::to_string(this->left()) + " are left; expected a complete scene file");
    }
  }
  std::uint8_t u8(const char* field)
  {
    this->need(1, field);
    return this->Bytes[this->Pos++];
  }
  /// An unsigned integer of sizeof(T) bytes, lowest first.
  template<typename T>
  T uintLE(const char* field)
  {
    this->need(sizeof(T), field);
    T v = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i)
      v |= T(this->Bytes[this->Pos++]) << (8 * i);
    return v;
  }
  std::uint32_t u32(const char* field) { return this->uintLE<std::uint32_t>(field); }
  std::uint64_t u64(const char* field) { return this->uintLE<std::uint64_t>(field); }
  std::int32_t i32(const char* field) { return std::int32_t(this->u32(field)); }
  float f32(const char* field)
  {
    const std::uint32_t u = this->u32(field);
    float v;
    std::memcpy(&v, &u, 4);
    return v;
  }
  double f64(const char* field)
  {
    const std::uint64_t u = this->u64(field);
    double v;
    std::memcpy(&v, &u, 8);
    return v;
  }
  bool flag(const char* field)
  {
    const std::uint8_t v = this->u8(field);
    if (v > 1)
      this->fail(std::string(field) + " is " + std::to_string(v) + "; expected 0 or 1");
    return v == 1;
  }
  glm::vec3 vec3(const char* field)
  {
    glm::vec3 v;
    for (int a = 0; a < 3; ++a)
      v[a] = this->f32(field);
    return v;
  }
  glm::dvec3 dvec3(const char* field)
  {
    glm::dvec3 v;
    for (int a = 0; a < 3; ++a)
      v[a] = this->f64(field);
    return v;
  }
  glm::ivec3 ivec3(const char* field)
  {
    glm::ivec3 v;
    for (int a = 0; a < 3; ++a)
      v[a] = this->i32(field);
    return v;
  }
  /// An enum stored as i32: fails outside [0, count).
  int enumValue(const char* field, int count)
  {
    const std::int32_t v = this->i32(field);
    if (v < 0 || v >= count)
      this->fail(std::string(field) + " is " + std::to_string(v) + "; expected 0.." +
                 std::to_string(count - 1));
    return v;
  }

private:
  const std::vector<std::uint8_t>& Bytes;
  std::size_t Pos;
  std::string What;
};

} // namespace scenefile
} // namespace amrdm
