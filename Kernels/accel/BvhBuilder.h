// Building the BVH of accel/Bvh.h (host): the records it is built over and the binned-SAH
// build itself (BvhBuilder.cpp). Host code.
#pragma once

#include "accel/Bvh.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

/// A primitive to build over: its box and its reference (28 bytes). Default-constructed records
/// are left uninitialised: the builder's arrays are written in full before they are read, and a
/// zeroing pass over them cost 1.4 % of a vortex build (perf, 2026-12-05).
struct BvhPrimBox
{
  glm::vec3 lo, hi;
  std::uint32_t ref;

  BvhPrimBox() {} // NOLINT(modernize-use-equals-default): `= default` would zero in resize()
  BvhPrimBox(const glm::vec3& lo_, const glm::vec3& hi_, std::uint32_t ref_)
    : lo(lo_)
    , hi(hi_)
    , ref(ref_)
  {
  }
};

/// Primitives per chunk when the build spreads one node's binning or partition over threads;
/// a thread's partition scratch holds at most one chunk of records (the memory budget counts
/// it, mesh/DualMeshBudget.cpp).
constexpr std::uint32_t kBvhChunkPrims = 1u << 15;

/// Binned-SAH build over the primitives' boxes (consumed: the build permutes them in place);
/// leaves hold at most `maxLeafSize` primitives unless they cannot be split. Deterministic: the
/// same tree, node for node, for every `threads` (worker threads, 0 = all cores; see
/// BvhBuilder.cpp).
Bvh buildBvh(DefaultInitVector<BvhPrimBox> prims, int maxLeafSize = 4, int threads = 1);

} // namespace amrdm
