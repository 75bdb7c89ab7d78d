// Bounding-volume hierarchy over gridlets and stitching elements, and its point query.
// The host builds it (BvhBuilder.cpp); traversal is host/device code.
#pragma once

#include "core/DefaultInitAllocator.h"
#include "core/HostDevice.h"
#include "mesh/ElementList.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

/// What a primitive reference points at: a gridlet, or one stitching-element kind per row of
/// mesh/ElementList.h (PrimTet = 1, ... in list order). Stored in the top 3 bits of the reference.
enum PrimType : std::uint32_t
{
  PrimGridlet = 0,
#define AMRDM_PRIM_TYPE(kind, ...) Prim##kind,
  AMRDM_ELEMENTS(AMRDM_PRIM_TYPE)
#undef AMRDM_PRIM_TYPE
    PrimTypeCount ///< not a type: the number of types
};
constexpr std::uint32_t kPrimTypeShift = 29;
constexpr std::uint32_t kPrimIndexMask = (1u << kPrimTypeShift) - 1u;
static_assert(PrimTypeCount <= (1u << (32 - kPrimTypeShift)),
  "more element kinds than a primitive reference's type bits can hold");
static_assert(PrimTypeCount == 1u + kElementKindCount, "one primitive type per element kind");

/// The primitive type of element kind `kind` and back.
AMRDM_HD constexpr std::uint32_t elementPrimType(int kind)
{
  return PrimGridlet + 1u + static_cast<std::uint32_t>(kind);
}
AMRDM_HD constexpr int primElementKind(std::uint32_t type)
{
  return static_cast<int>(type) - static_cast<int>(PrimGridlet + 1u);
}
/// True for the type of an element kind in the list (not a gridlet, not out of range).
AMRDM_HD constexpr bool isElementPrimType(std::uint32_t type)
{
  return type > PrimGridlet && type < PrimTypeCount;
}

AMRDM_HD std::uint32_t makePrimRef(std::uint32_t type, std::uint32_t index)
{
  return (type << kPrimTypeShift) | index;
}
AMRDM_HD std::uint32_t primType(std::uint32_t ref)
{
  return ref >> kPrimTypeShift;
}
AMRDM_HD std::uint32_t primIndex(std::uint32_t ref)
{
  return ref & kPrimIndexMask;
}

/// 32 bytes. Inner node: count == 0, children at `first` and `first + 1`.
/// Leaf: `count` primitive references starting at `first`.
struct BvhNode
{
  glm::vec3 lo;
  std::uint32_t first;
  glm::vec3 hi;
  std::uint32_t count;
};
static_assert(sizeof(BvhNode) == 32, "BvhNode must stay 32 bytes");

struct BvhView
{
  const BvhNode* nodes = nullptr;
  const std::uint32_t* prims = nullptr;
  std::uint32_t numNodes = 0;
  /// Optional culling masks (see PrimitiveCulling.h): a node or primitive slot whose mask is 0
  /// is skipped, as if absent. Null = nothing culled.
  const std::uint8_t* nodeVisible = nullptr;
  const std::uint8_t* slotVisible = nullptr;
};

/// Deepest tree the traversal stack supports; the builder never exceeds it.
constexpr int kBvhMaxDepth = 64;

struct Bvh
{
  DefaultInitVector<BvhNode> nodes;
  DefaultInitVector<std::uint32_t> prims;
  int depth = 0;

  BvhView view() const
  {
    BvhView v;
    v.nodes = this->nodes.data();
    v.prims = this->prims.data();
    v.numNodes = static_cast<std::uint32_t>(this->nodes.size());
    return v;
  }
  std::uint64_t bytes() const
  {
    return this->nodes.size() * sizeof(BvhNode) + this->prims.size() * sizeof(std::uint32_t);
  }
};

/// Calls visit(ref) for every primitive whose box contains p, until visit returns true.
/// Returns true if some visit returned true. p may be float or double; boxes are float, rounded
/// outwards by the builder, so they contain every point their primitive claims.
template<typename T, typename Visit>
AMRDM_HD bool bvhPointQuery(const BvhView& bvh, const glm::vec<3, T>& p, Visit&& visit)
{
  if (bvh.numNodes == 0)
  {
    return false;
  }
  std::uint32_t stack[kBvhMaxDepth];
  int top = 0;
  std::uint32_t node = 0;
  for (;;)
  {
    const BvhNode& n = bvh.nodes[node];
    const bool inside = (!bvh.nodeVisible || bvh.nodeVisible[node]) && p.x >= n.lo.x &&
                        p.y >= n.lo.y && p.z >= n.lo.z && p.x <= n.hi.x && p.y <= n.hi.y &&
                        p.z <= n.hi.z;
    if (inside)
    {
      if (n.count == 0)
      {
        stack[top++] = n.first + 1;
        node = n.first;
        continue;
      }
      for (std::uint32_t i = 0; i < n.count; ++i)
      {
        if (bvh.slotVisible && !bvh.slotVisible[n.first + i])
        {
          continue;
        }
        if (visit(bvh.prims[n.first + i]))
        {
          return true;
        }
      }
    }
    if (top == 0)
    {
      return false;
    }
    node = stack[--top];
  }
}

} // namespace amrdm
