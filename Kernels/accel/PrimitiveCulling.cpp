#include "accel/PrimitiveCulling.h"

#include "core/ParallelFor.h"
#include "core/Tolerances.h"

#include <limits>

namespace amrdm
{

namespace
{
// A primitive's range is widened by the value-range pads of core/Tolerances.h (the same as the
// majorant grid's): element tests extrapolate by up to their inside and residual tolerances.

glm::vec2 primitiveRange(const DualMesh& mesh, std::uint32_t ref)
{
  glm::vec2 r(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max());
  const std::uint32_t type = primType(ref), index = primIndex(ref);
  if (type == PrimGridlet)
  {
    const GridletHeader& g = mesh.gridlets[index];
    const std::size_t n = std::size_t(g.dims.x + 1) * (g.dims.y + 1) * (g.dims.z + 1);
    for (std::size_t i = 0; i < n; ++i)
    {
      const float v = mesh.gridletScalars[g.begin + i];
      if (v == v)
      {
        r = glm::vec2(glm::min(r.x, v), glm::max(r.y, v));
      }
    }
  }
  else if (isElementPrimType(type)) // any other type claims nothing: an empty range
  {
    const int k = primElementKind(type);
    const int n = elementCorners(k);
    for (int c = 0; c < n; ++c)
    {
      const float v = mesh.vertices[mesh.elementIndices[k][std::size_t(index) * n + c]].value;
      r = glm::vec2(glm::min(r.x, v), glm::max(r.y, v));
    }
  }
  if (r.x <= r.y)
  {
    const float pad =
      kRangePadRelative * (r.y - r.x) + kRangePadUlps * glm::max(std::abs(r.x), std::abs(r.y));
    r += glm::vec2(-pad, pad);
  }
  return r;
}
} // namespace

PrimitiveCulling buildPrimitiveRanges(const DualMesh& mesh, int threads)
{
  PrimitiveCulling c;
  const std::size_t slots = mesh.bvh.prims.size();
  c.slotRange.resize(slots);
  parallelFor((slots + 1023) / 1024,
    threads,
    [&](std::size_t chunk)
    {
      const std::size_t end = std::min(slots, (chunk + 1) * 1024);
      for (std::size_t s = chunk * 1024; s < end; ++s)
      {
        const glm::vec2 r = primitiveRange(mesh, mesh.bvh.prims[s]);
        c.slotRange[s] = std::uint32_t(rangeCode(r.x)) | (std::uint32_t(rangeCode(r.y)) << 16);
      }
    });
  return c;
}

void updatePrimitiveVisibility(PrimitiveCulling& c,
  const Bvh& bvh,
  const TransferFunctionView& tf,
  int threads)
{
  const std::size_t slots = c.slotRange.size();
  c.slotVisible.resize(slots);
  parallelFor((slots + 4095) / 4096,
    threads,
    [&](std::size_t chunk)
    {
      const std::size_t end = std::min(slots, (chunk + 1) * 4096);
      for (std::size_t s = chunk * 4096; s < end; ++s)
      {
        const glm::vec2 r = c.range(s);
        c.slotVisible[s] = tfMaxExtinction(tf, r.x, r.y) > 0.0f;
      }
    });
  c.visibleSlots = 0;
  for (std::uint8_t v : c.slotVisible)
  {
    c.visibleSlots += v;
  }
  // A node is visible where any slot below it is. Children always come after their parent, so
  // one backward sweep fills the nodes.
  const std::size_t nodes = bvh.nodes.size();
  c.nodeVisible.assign(nodes, 0);
  for (std::size_t i = nodes; i-- > 0;)
  {
    const BvhNode& n = bvh.nodes[i];
    std::uint8_t visible = 0;
    if (n.count == 0)
    {
      visible = c.nodeVisible[n.first] | c.nodeVisible[n.first + 1];
    }
    else
    {
      for (std::uint32_t k = 0; k < n.count; ++k)
      {
        visible |= c.slotVisible[n.first + k];
      }
    }
    c.nodeVisible[i] = visible;
  }
}

} // namespace amrdm
