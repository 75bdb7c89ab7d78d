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
        c.slotRange[s] = primitiveRange(mesh, mesh.bvh.prims[s]);
      }
    });
  // Children always come after their parent, so one backward sweep fills the nodes.
  const std::size_t nodes = mesh.bvh.nodes.size();
  c.nodeRange.assign(
    nodes, glm::vec2(std::numeric_limits<float>::max(), -std::numeric_limits<float>::max()));
  for (std::size_t i = nodes; i-- > 0;)
  {
    const BvhNode& n = mesh.bvh.nodes[i];
    glm::vec2& r = c.nodeRange[i];
    if (n.count == 0)
    {
      for (std::uint32_t k = 0; k < 2; ++k)
      {
        const glm::vec2& cr = c.nodeRange[n.first + k];
        r = glm::vec2(glm::min(r.x, cr.x), glm::max(r.y, cr.y));
      }
    }
    else
    {
      for (std::uint32_t k = 0; k < n.count; ++k)
      {
        const glm::vec2& sr = c.slotRange[n.first + k];
        r = glm::vec2(glm::min(r.x, sr.x), glm::max(r.y, sr.y));
      }
    }
  }
  return c;
}

void updatePrimitiveVisibility(PrimitiveCulling& c, const TransferFunctionView& tf, int threads)
{
  c.slotVisible.resize(c.slotRange.size());
  c.nodeVisible.resize(c.nodeRange.size());
  parallelFor((c.slotRange.size() + 4095) / 4096,
    threads,
    [&](std::size_t chunk)
    {
      const std::size_t end = std::min(c.slotRange.size(), (chunk + 1) * 4096);
      for (std::size_t s = chunk * 4096; s < end; ++s)
      {
        c.slotVisible[s] = tfMaxExtinction(tf, c.slotRange[s].x, c.slotRange[s].y) > 0.0f;
      }
    });
  for (std::size_t i = 0; i < c.nodeRange.size(); ++i)
  {
    c.nodeVisible[i] = tfMaxExtinction(tf, c.nodeRange[i].x, c.nodeRange[i].y) > 0.0f;
  }
  c.visibleSlots = 0;
  for (std::uint8_t v : c.slotVisible)
  {
    c.visibleSlots += v;
  }
}

} // namespace amrdm
