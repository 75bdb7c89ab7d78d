// Clusters perfect dual cubes into gridlets: per level, every aligned block of G^3 dual cells
// that holds at least one perfect cube becomes one gridlet with tight bounds; its (dims+1)^3
// scalars are the level's leaf values, NaN where a vertex is not a leaf of that level. Boundary
// cubes (mesh/DualCellDiscovery.h) put vertices beyond a domain face: they hold the ghost's value
// (the clamped cell's), and the gridlet's box is cut at the face (gridletGridBox).
#pragma once

#include "mesh/AmrHierarchy.h"
#include "accel/CellLocator.h"
#include "mesh/DualMesh.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace amrdm
{

/// `length` perfect cubes with lower corners lower, lower + (1,0,0), ... on `level`.
struct PerfectCubeRun
{
  int level;
  glm::ivec3 lower;
  int length;
};

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

/// One gridlet's dual cells: lower corners lo..hi (inclusive) on `level`.
struct GridletRange
{
  int level;
  glm::ivec3 lo, hi;
};

/// Scalars of gridlet r: one per corner of its dual cells, (dims + 1)^3 (the builder's offsets
/// and the memory budget's count).
inline std::uint64_t gridletScalarCount(const GridletRange& r)
{
  const glm::ivec3 d = r.hi - r.lo + 2; // dims + 1
  return static_cast<std::uint64_t>(d.x) * static_cast<std::uint64_t>(d.y) *
         static_cast<std::uint64_t>(d.z);
}

/// Per level, the lattice position where the aligned blocks of G dual cells a side begin: one
/// cell below the domain's lower faces, so that a boundary cube (lower corner at the ghost
/// position) shares its block with the cubes behind it and no gridlet exceeds G a side.
std::vector<glm::ivec3> gridletBlockOrigins(const AmrHierarchy& amr);

/// The gridlet layout (the builder's and the memory budget's): the bounding range of the perfect
/// cubes in each block, ordered by level, then block z, y, x. On `threads` threads (0 = all
/// cores); the result does not depend on them.
std::vector<GridletRange> gridletLayout(const AmrHierarchy& amr,
  const std::vector<PerfectCubeRun>& runs,
  int gridletSize,
  int threads = 1);

/// Called with the indices of blocks whose values and states the build no longer reads.
using BlockRelease = std::function<void(const std::vector<std::uint32_t>&)>;

/// Fills mesh.gridlets and mesh.gridletScalars (ordered by level, then gridlet z, y, x). With
/// `releaseBlocks`, the scalars are filled one z-slab of gridlets at a time and after each slab
/// it is called with the blocks whose values and states no later gridlet reads (every block is
/// named once, the last ones after the last slab): a caller that owns the input frees them there,
/// so the input copy shrinks while the scalars grow.
void buildGridlets(const AmrHierarchy& amr,
  const CellLocator& locator,
  const std::vector<PerfectCubeRun>& runs,
  int gridletSize,
  int threads,
  DualMesh& mesh,
  const BlockRelease& releaseBlocks = {});

} // namespace amrdm
