// Fills the gridlets of a layout (mesh/GridletLayout.h: per level, one gridlet with tight bounds
// per aligned block of G^3 dual cells that holds a perfect cube): its (dims+1)^3
// scalars are the level's leaf values, NaN where a vertex is not a leaf of that level. Boundary
// cubes (mesh/DualCellDiscovery.h) put vertices beyond a domain face: they hold the ghost's value
// (the clamped cell's), and the gridlet's box is cut at the face (gridletGridBox).
#pragma once

#include "mesh/AmrHierarchy.h"
#include "accel/CellLocator.h"
#include "mesh/DualMesh.h"
#include "mesh/GridletLayout.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace amrdm
{

/// Grid-space box of gridlet g: its dual cells' box cut at the domain faces (boundary cubes reach
/// half a cell beyond them; their field there is never sampled).
inline void gridletGridBox(const DualMesh& mesh,
  const GridletHeader& g,
  glm::dvec3& lo,
  glm::dvec3& hi)
{
  const double w = mesh.levelWidth[static_cast<std::size_t>(g.level)];
  const double o = mesh.gridletOrigin; // 0.5: dual cells; 0: vertex data's primal cells
  lo = glm::max((glm::dvec3(g.lower) + o) * w, glm::dvec3(mesh.domainLower));
  hi = glm::min((glm::dvec3(g.lower + g.dims) + o) * w, glm::dvec3(mesh.domainUpper));
}

/// Called with the indices of blocks whose values and states the build no longer reads.
using BlockRelease = std::function<void(const std::vector<std::uint32_t>&)>;

/// Fills mesh.gridlets and mesh.gridletScalars (ordered by level, then gridlet z, y, x). With
/// `releaseBlocks`, the scalars are filled one z-slab of gridlets at a time and after each slab
/// it is called with the blocks whose values and states no later gridlet reads (every block is
/// named once, the last ones after the last slab): a caller that owns the input frees them there,
/// so the input copy shrinks while the scalars grow.
void buildGridlets(const AmrHierarchy& amr,
  const CellLocator& locator,
  const std::vector<GridletRange>& layout,
  int gridletSize,
  int threads,
  DualMesh& mesh,
  const BlockRelease& releaseBlocks = {});

} // namespace amrdm
