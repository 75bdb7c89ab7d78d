// The dual-mesh build's memory budget: what the mesh and the build's temporaries will take, by
// category and at their true sizes, before anything large is allocated. Host code.
//
// Two censuses feed one estimate (estimateFromCensus): an upper bound from cell states and the
// blocks' one-cell halos (boundDualCells: a few byte passes and a halo lookup, no discovery;
// the build first tries its looser form from block sizes alone), and, only
// when that bound exceeds the limit, a counting pass over dual-cell discovery (countDualCells;
// also behind the public estimateDualMeshMemory()). From the counting pass, counted exactly:
// element indices (4 B per corner, per kind of mesh/ElementList.h), stitching vertices (16 B per
// distinct corner cell, a bit per AMR cell finds them), gridlet headers and scalars (the layout
// of GridletLayout.h, gridletLayout: one gridlet per aligned G^3 block of a level's perfect cubes,
// (dims+1)^3 floats), BVH primitive references (4 B per primitive), the discovery pass's element
// records (sizeof(ClassifiedElement) each, reserved exactly), the gridlet pieces, the
// per-thread neighbourhood scratch, the id -> vertex rank bitmap (12 B per 64 AMR cells, 8 B per
// vertex id)
// and the BVH build's boxes, references, order, centroids and node reserve. Estimated: the
// number of BVH nodes (kBvhNodesPerPrimitive). The builder holds no copy of the input values (it
// reads the AmrHierarchy, which the caller owns; not counted: a hierarchy handed over to
// buildDualMesh(AmrHierarchy&&) shrinks block by block during the gridlet fill and is gone
// before the BVH step, so the peak's steps below are unchanged by it).
#pragma once

#include "mesh/DualMesh.h"
#include "mesh/ElementList.h"
#include "mesh/GridletLayout.h"

#include <cstdint>
#include <string>
#include <vector>

namespace amrdm
{

class BoundaryLayer;

/// BVH nodes per primitive at leaf size 4 (binned SAH of BvhBuilder.cpp; measured 0.58-0.64 on
/// the real sets with more than 10^3 primitives, TestMemoryBudget).
constexpr double kBvhNodesPerPrimitive = 0.62;

/// The build's memory, by category, before it runs (estimateDualMeshMemory()).
struct DualMeshMemoryEstimate
{
  /// The finished mesh, as DualMesh::memoryReport() will report it (same categories).
  MemoryReport mesh;
  std::int64_t elements[kElementKindCount] = {}; ///< per kind (mesh/ElementList.h)
  std::int64_t gridlets = 0;
  std::int64_t vertices = 0;
  std::int64_t primitives = 0; ///< gridlets plus elements: BVH references
  // Temporaries of the build (freed before it returns).
  std::uint64_t elementRecords = 0;  ///< discovery's classified elements, until step 2 ends
  std::uint64_t gridletPieces = 0;   ///< perfect cubes per item and aligned block, until the layout
  std::uint64_t workItemScratch = 0; ///< per-thread padded neighbourhoods during discovery
  std::uint64_t gridletLayout = 0;   ///< the layout's ranges, until the gridlets are built
  std::uint64_t vertexMap = 0;       ///< id -> vertex rank bitmap and vertex ids of step 2
  std::uint64_t bvhBuild = 0;        ///< the BVH build's records, subtree nodes and scratch

  /// Largest live total over the build's steps (discovery, elements, gridlets, BVH).
  std::uint64_t peak() const;
  std::string toJson() const;
};

namespace detail
{
/// What the counting pass found (countDualCells), or upper bounds of it (boundDualCells).
struct DualCellCensus
{
  bool upperBound = false; ///< bounds: BVH nodes at their most, 2 per primitive
  std::int64_t elements[kElementKindCount] = {}; ///< per kind
  std::int64_t gridlets = 0;
  std::uint64_t gridletScalars = 0; ///< values
  std::int64_t gridletPieces = 0;   ///< items' gridlet pieces (mesh/GridletLayout.h)
  std::int64_t vertices = 0;        ///< distinct stitching-element corners
  std::int64_t totalCells = 0;      ///< AMR cells (CellLocator ids)
  std::int64_t scratchCells = 0;    ///< padded cells of the largest work item, per thread
  int threads = 1;
  std::vector<std::int64_t> itemElements; ///< elements per work item (exact reserves)
};

struct WorkItem;

/// Upper bounds of the census from cell states alone (a few byte passes, no discovery): a leaf
/// cell whose 3x3x3 neighbourhood lies inside its block and holds only leaves emits no element,
/// any other emits at most 8 (each a hex, the most corners); the gridlets are at most one full
/// G^3 gridlet per aligned block a block's cells touch. When the bound's peak fits the limit the
/// build needs no counting pass. With `everyCellEmits` every cell counts as an emitter (no
/// state or halo pass at all; a looser bound that the build tries first, since on a machine with
/// memory to spare it already fits).
DualCellCensus boundDualCells(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const std::vector<WorkItem>& items,
  int gridletSize,
  int threads,
  bool everyCellEmits = false);

/// The counting pass: discovery of every work item, keeping its gridlet pieces and counting
/// its elements per kind and their distinct corners (a bit per AMR cell); the element records
/// are dropped item by item. Throws std::length_error when its own buffers exceed `limit`
/// (0 = no limit).
DualCellCensus countDualCells(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const std::vector<WorkItem>& items,
  int gridletSize,
  int threads,
  std::uint64_t limit);

/// Throws std::length_error when the estimated peak exceeds `limit` (0 = no limit), with the
/// estimate by category, the limit, about how many leaf cells would fit and, given the hierarchy,
/// the most levels that would (levelsThatFit()).
void checkBudget(const DualMeshMemoryEstimate& estimate,
  std::uint64_t limit,
  const AmrHierarchy* amr = nullptr);

/// The most levels (1..numLevels) whose hierarchy would fit in `limit`, scaling the estimate's
/// peak by the leaf cells of the hierarchy cut after those levels (a cut level's visible cells
/// all become leaves); 0 when not even level 0 would. Sets `leafCells` to that hierarchy's.
int levelsThatFit(const AmrHierarchy& amr,
  const DualMeshMemoryEstimate& estimate,
  std::uint64_t limit,
  std::int64_t& leafCells);

/// The estimate from a census, for BVH leaf size `leafSize`.
DualMeshMemoryEstimate estimateFromCensus(const DualCellCensus& census,
  int leafSize,
  std::int64_t leafCells);
} // namespace detail

} // namespace amrdm
