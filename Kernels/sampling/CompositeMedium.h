// The medium of a data-parallel region whose scattered and shadow rays must see the whole
// domain (DistributionMode Proxy): the exact dual mesh of the region inside its box, and a
// coarse replicated proxy of the whole domain (the level-0 dual mesh) outside it. Camera rays
// are clipped to the box, so what the camera sees directly is exact; light that arrives from,
// or is shadowed by, the other regions is approximated by the proxy. Both meshes live in the
// same scene frame. Same interface as DualMeshMedium (Media.h). Host/device code.
#pragma once

#include "sampling/Media.h"

namespace amrdm
{

struct CompositeMedium
{
  DualMeshMedium inner; ///< exact: the region's mesh (valid inside [lo, hi] and a ghost band)
  DualMeshMedium outer; ///< approximate: the proxy of the whole domain
  glm::vec3 lo{ 0.0f }, hi{ 0.0f }; ///< the region's box, scene frame

  /// Points on the box's faces belong to the inner mesh (its ghost band covers them).
  AMRDM_HD bool inside(const glm::vec3& p) const
  {
    return glm::all(glm::greaterThanEqual(p, this->lo)) &&
           glm::all(glm::lessThanEqual(p, this->hi));
  }

  AMRDM_HD bool value(const glm::vec3& p,
    float& v,
    TraceCounters& counters,
    SampleHit* hit = nullptr) const
  {
    if (this->inside(p))
    {
      return this->inner.value(p, v, counters, hit);
    }
    // The outer mesh keeps its own "previous primitive" hint, and does not read or write the
    // ray-hint table, whose primitives are the inner mesh's.
    const std::uint32_t innerHint = counters.lastPrimitive;
    const std::uint32_t slot = counters.hintSlot;
    counters.lastPrimitive = counters.lastOuterPrimitive;
    counters.hintSlot = ~0u;
    const bool found = this->outer.value(p, v, counters, hit);
    counters.lastOuterPrimitive = counters.lastPrimitive;
    counters.lastPrimitive = innerHint;
    counters.hintSlot = slot;
    return found;
  }
  AMRDM_HD glm::vec4 rgba(const glm::vec3& p, TraceCounters& counters) const
  {
    return fieldRgba(*this, this->inner.tf, p, counters);
  }
  AMRDM_HD MediumSample sample(const glm::vec3& p, TraceCounters& counters) const
  {
    return fieldSample(*this, this->inner.tf, p, counters);
  }
  AMRDM_HD float unitDistance() const { return this->inner.tf.unitDistance; }
};

} // namespace amrdm
