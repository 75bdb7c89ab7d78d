// The majorant grid of a CompositeMedium (sampling/CompositeMedium.h): the exact region mesh
// inside a box, the coarse proxy of the whole domain outside it. The composite grid has the
// outer (proxy) grid's bounds and resolution; each macrocell's value range is the union of the
// outer range (when the macrocell reaches outside the box) and the ranges of every inner
// macrocell that overlaps its part inside the box, so that the majorant bounds whichever mesh
// answers at any point of it. Host code.
#pragma once

#include "accel/MajorantGrid.h"

namespace amrdm
{

/// Macrocells per axis for the composite grid over `domainLo`..`domainHi`: about the inner
/// grid's macrocell size, at most kDefaultMaxMacrocellsPerAxis per axis, at least 1.
glm::ivec3 compositeMajorantResolution(const MajorantGrid& inner,
  const glm::vec3& domainLo,
  const glm::vec3& domainHi);

/// Ranges and cell widths of the composite grid (majorants left empty: updateMajorants()).
/// `outer` must hold ranges (buildMajorantRanges of the proxy mesh); `inner` the region
/// mesh's ranges; [lo, hi] the region's box, scene frame. Throws std::invalid_argument when a
/// grid has no ranges or the box is empty.
MajorantGrid compositeMajorantRanges(const MajorantGrid& outer,
  const MajorantGrid& inner,
  const glm::vec3& lo,
  const glm::vec3& hi);

} // namespace amrdm
