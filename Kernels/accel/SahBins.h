// The binned surface-area heuristic's pieces (accel/BvhBuilder.cpp): boxes, a range's bounds
// and centroid bounds, and per axis the bins of its centroids. Host code.
#pragma once

#include "accel/BvhBuilder.h"

#include <algorithm>
#include <limits>

namespace amrdm
{
namespace sah
{

constexpr int kSahBins = 16;

struct Box
{
  glm::vec3 lo{ std::numeric_limits<float>::max() };
  glm::vec3 hi{ -std::numeric_limits<float>::max() };
  void grow(const glm::vec3& a, const glm::vec3& b)
  {
    lo = glm::min(lo, a);
    hi = glm::max(hi, b);
  }
  void grow(const Box& o) { grow(o.lo, o.hi); }
  float area() const
  {
    if (lo.x > hi.x)
    {
      return 0.0f;
    }
    const glm::vec3 d = hi - lo;
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
};

/// A range's bounds and the bounds of its centroids.
struct RangeBounds
{
  Box bounds, cbounds;
  void grow(const BvhPrimBox& p, const glm::vec3& c)
  {
    this->bounds.grow(p.lo, p.hi);
    this->cbounds.grow(c, c);
  }
  void grow(const RangeBounds& o)
  {
    this->bounds.grow(o.bounds);
    this->cbounds.grow(o.cbounds);
  }
};

/// Per axis, the bins of a range's centroids over its centroid bounds.
struct Bins
{
  Box box[3][kSahBins];
  std::uint32_t count[3][kSahBins] = {};
  void grow(const Bins& o)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      for (int b = 0; b < kSahBins; ++b)
      {
        this->box[axis][b].grow(o.box[axis][b]);
        this->count[axis][b] += o.count[axis][b];
      }
    }
  }
};

inline glm::vec3 centroidOf(const BvhPrimBox& p)
{
  return 0.5f * (p.lo + p.hi);
}

/// Bins along each axis of a centroid bounds: scale = bins / extent, 0 for a flat axis
/// (which is not binned).
struct BinMap
{
  glm::vec3 lo, scale;
  bool live[3];
  explicit BinMap(const Box& cbounds)
    : lo(cbounds.lo)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      const float extent = cbounds.hi[axis] - cbounds.lo[axis];
      this->live[axis] = extent > 0.0f;
      this->scale[axis] = this->live[axis] ? kSahBins / extent : 0.0f;
    }
  }
  int bin(const glm::vec3& c, int axis) const
  {
    return std::min(kSahBins - 1, static_cast<int>((c[axis] - this->lo[axis]) * this->scale[axis]));
  }
};

} // namespace sah
} // namespace amrdm
