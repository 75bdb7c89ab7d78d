// Primitives the transfer function makes invisible cost nothing at sampling time: every BVH
// primitive slot keeps the value range it covers (built once per mesh, 4 bytes: two 16-bit
// order-preserving codes of the floats, rounded outwards, so the range stored holds every value
// and is at most 2^-7 of a value wider at each end); a transfer function change recomputes one
// visibility byte per slot (max extinction over the range > 0) and per node (any slot below it
// visible). The point query then skips invisible subtrees and primitives, and a skipped
// primitive reads as "no data", which is exactly its zero density. Host code.
#pragma once

#include "mesh/DualMesh.h"
#include "sampling/TransferFunction.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace amrdm
{

/// 16-bit code of float v, monotonic in v over every float that is not NaN (the top half of
/// the order-preserving integer of v's bits). A range [a, b] is kept as (code(a), code(b)) and
/// read back as [rangeLow(code(a)), rangeHigh(code(b))], which holds it.
inline std::uint16_t rangeCode(float v)
{
  std::uint32_t u;
  std::memcpy(&u, &v, sizeof(u));
  u = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
  return std::uint16_t(u >> 16);
}
/// The smallest float with code c (-inf for the smallest code's negative floats: conservative).
inline float rangeLow(std::uint16_t c)
{
  std::uint32_t u = std::uint32_t(c) << 16;
  u = (u & 0x80000000u) ? (u & 0x7fffffffu) : ~u;
  float v;
  std::memcpy(&v, &u, sizeof(v));
  return v == v ? v : -std::numeric_limits<float>::infinity();
}
/// The largest float with code c (+inf where that would be past the finite floats).
inline float rangeHigh(std::uint16_t c)
{
  std::uint32_t u = (std::uint32_t(c) << 16) | 0xffffu;
  u = (u & 0x80000000u) ? (u & 0x7fffffffu) : ~u;
  float v;
  std::memcpy(&v, &u, sizeof(v));
  return v == v ? v : std::numeric_limits<float>::infinity();
}

struct PrimitiveCulling
{
  /// Per BVH primitive slot: its values' (min, max) as rangeCode(min) | rangeCode(max) << 16;
  /// an empty range (no value) has min > max.
  std::vector<std::uint32_t> slotRange;
  std::vector<std::uint8_t> slotVisible, nodeVisible; ///< transfer-function derived
  std::int64_t visibleSlots = 0;

  /// The value range slot s stands for (holds every value of its primitive).
  glm::vec2 range(std::size_t s) const
  {
    return glm::vec2(rangeLow(std::uint16_t(this->slotRange[s] & 0xffffu)),
      rangeHigh(std::uint16_t(this->slotRange[s] >> 16)));
  }

  /// Host bytes: 4 B of range and 1 B of visibility per slot, 1 B of visibility per node.
  std::uint64_t bytes() const
  {
    return std::uint64_t(this->slotRange.size()) * sizeof(std::uint32_t) +
           std::uint64_t(this->slotVisible.size() + this->nodeVisible.size());
  }

  /// `bvh` with the culling masks attached (masks must be current).
  BvhView apply(BvhView bvh) const
  {
    if (!this->slotVisible.empty())
    {
      bvh.slotVisible = this->slotVisible.data();
      bvh.nodeVisible = this->nodeVisible.data();
    }
    return bvh;
  }
};

/// Value ranges of every primitive slot of mesh.bvh.
PrimitiveCulling buildPrimitiveRanges(const DualMesh& mesh, int threads = 0);

/// Recomputes the visibility masks for a transfer function; `bvh` is the one the ranges were
/// built from (its nodes get the union of their slots' visibility).
void updatePrimitiveVisibility(PrimitiveCulling& culling,
  const Bvh& bvh,
  const TransferFunctionView& tf,
  int threads = 0);

} // namespace amrdm
