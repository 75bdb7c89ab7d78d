// Primitives the transfer function makes invisible cost nothing at sampling time: every BVH
// primitive slot and node keeps the value range it covers (built once per mesh); a transfer
// function change recomputes one visibility byte per slot and node (max extinction over the
// range > 0). The point query then skips invisible subtrees and primitives, and a skipped
// primitive reads as "no data", which is exactly its zero density. Host code.
#pragma once

#include "mesh/DualMesh.h"
#include "sampling/TransferFunction.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

struct PrimitiveCulling
{
  std::vector<glm::vec2> slotRange; ///< per BVH primitive slot: (min, max) of its values
  std::vector<glm::vec2> nodeRange; ///< per BVH node: union of its subtree's ranges
  std::vector<std::uint8_t> slotVisible, nodeVisible; ///< transfer-function derived
  std::int64_t visibleSlots = 0;

  /// Host bytes: 8 B of range and 1 B of visibility per slot and per node.
  std::uint64_t bytes() const
  {
    return std::uint64_t(this->slotRange.size() + this->nodeRange.size()) * sizeof(glm::vec2) +
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

/// Value ranges of every primitive and node of mesh.bvh.
PrimitiveCulling buildPrimitiveRanges(const DualMesh& mesh, int threads = 0);

/// Recomputes the visibility masks for a transfer function.
void updatePrimitiveVisibility(PrimitiveCulling& culling,
  const TransferFunctionView& tf,
  int threads = 0);

} // namespace amrdm
