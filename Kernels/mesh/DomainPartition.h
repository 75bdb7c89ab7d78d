// The data-parallel partition of an AMR domain: a kd-tree over the level-0 index space, computed
// from the hierarchy's metadata alone (block boxes and ratios), so every MPI rank computes the
// same boxes with no communication; and the ghost band a region needs so that its own dual mesh
// equals the serial one inside the region (exact, and C0 across region faces).
//
// - Cuts lie on level-0 cell faces, hence on a cell face of every level: each leaf cell has
//   exactly one owner region.
// - Balanced by leaf cells (metadata coverage: a level-L cell counts 1 - 1/r_L^3, the part of its
//   parent it turns from leaf to refined), recursive bisection of the longest axis, ranks split
//   floor(n/2) / ceil(n/2) with the weight split in proportion: any region count works, odd counts
//   and regions that hold no block included. No region is ever empty.
// - Ghost band (tight rule, properly nested levels): every cell of level L whose box touches the
//   region grown by one level-L cell (L-infinity: faces, edges, corners). A dual element that
//   intersects the region only has vertices inside that band (TestDomainPartition checks it
//   sample for sample against the serial mesh). Leaf / refined status of the band comes from the
//   global hierarchy, never from local coverage: coarse cells whose children fall outside the
//   band stay "refined" (holes outside the region, harmless because rays are clipped to it).
#pragma once

#include "mesh/AmrHierarchy.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace amrdm
{

/// An axis-aligned box of level-0 cells, [lower, upper) in level-0 index space.
struct PartitionBox
{
  glm::ivec3 lower{ 0 };
  glm::ivec3 upper{ 0 };

  glm::ivec3 dims() const { return this->upper - this->lower; }
  std::int64_t numCells() const
  {
    const glm::ivec3 d = this->dims();
    return static_cast<std::int64_t>(d.x) * d.y * d.z;
  }
};

/// The partition of a domain into one box per region (MPI rank), and the kd-tree's weights.
struct DomainPartition
{
  PartitionBox domain;               ///< bounding box of the level-0 blocks
  std::vector<PartitionBox> regions; ///< one per region, disjoint, tiling `domain`
  std::vector<double> leafCells;     ///< estimated leaf cells per region (the balance weight)

  /// Region box in grid space (finest units): lower/upper corners.
  void gridBox(const AmrHierarchy& amr, int region, glm::dvec3& lo, glm::dvec3& hi) const;
};

/// The kd-tree partition of `amr`'s level-0 domain into `numRegions` boxes. Reads only levels,
/// block boxes and ratios (values and states may be empty). Throws std::invalid_argument when
/// numRegions < 1, when the hierarchy has no level-0 block, or when numRegions exceeds the
/// number of level-0 cells of the domain (each region needs at least one).
DomainPartition partitionDomain(const AmrHierarchy& amr, int numRegions);

/// The hierarchy a region needs: every block cropped to the region plus the ghost band (see the
/// file comment), with explicit cell states taken from the global hierarchy (finalizeCellStates
/// is applied to a copy when `amr` has blocks without states). Blocks that miss the band are left
/// out. Values are copied; blocks of `amr` with no values (metadata only, data on another rank)
/// that reach into the band throw std::invalid_argument naming the block.
AmrHierarchy regionHierarchy(const AmrHierarchy& amr, const PartitionBox& region);

/// Level-L cell range [lower, upper) that region + ghost band covers (clipped to nothing else).
void regionCellRange(const AmrHierarchy& amr,
  const PartitionBox& region,
  int level,
  glm::ivec3& lower,
  glm::ivec3& upper);

} // namespace amrdm
