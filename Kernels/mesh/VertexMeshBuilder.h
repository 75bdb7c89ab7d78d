// The mesh of vertex-centred (point-data) AMR: no dual. Each level's leaf cells are trilinear
// cells over their own corner values, so a block's vertex lattice maps straight to gridlets of
// primal cells (DualMesh::gridletOrigin = 0: a level-L gridlet vertex i sits at (lower + i) *
// width). Cells covered by a finer level (or hidden, or with a non-finite corner) are empty.
// The same BVH, majorants and samplers as the dual mesh; no stitching elements.
//
// Continuity across level transitions ("coarse wins on the interface, fine inside"): levels are
// resolved coarsest first; a level-L vertex that lies on the closure of a coarser leaf cell (the
// faces, edges and corners a finer block shares with the coarser region it sits in, hanging
// nodes included) takes that cell's trilinear interpolant at its position, computed from the
// coarser level's already resolved corners. A fine cell's face on the interface is then the
// coarse face's bilinear restriction, so the field is C0 everywhere and reproduces linear
// fields exactly. Every other vertex keeps its own level's value: where levels disagree, the
// finer level wins inside its region (the coarse cells there are blanked) and the coarser wins
// on the boundary of that region. A vertex shared by blocks of one level takes the value of the
// lowest-numbered block of that level that holds it. Host code; parallel and deterministic.
#pragma once

#include "accel/CellLocator.h"
#include "mesh/DualMeshBuilder.h"

#include <vector>

namespace amrdm
{

/// Builds the vertex-centred mesh of `amr` (association Points, states finalized). A coarse cell
/// that finer blocks cover only in part is refined all the same (finalizeCellStates): its
/// uncovered part is a hole, so the union of a level's blocks should cover whole parent cells
/// (the VTK intake requires every refined box to be aligned with them). Throws
/// std::invalid_argument on invalid input and std::length_error when the estimate exceeds
/// options.memoryLimit. buildDualMesh() calls it for Points hierarchies.
DualMesh buildVertexMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options = {});

/// What buildVertexMesh() will allocate: the gridlet layout is computed (cell states only) and
/// counted exactly; BVH nodes are bounded by 2 per primitive; `vertexMap` holds the resolved
/// copy of the vertex values (4 B per vertex), freed before the BVH is built.
DualMeshMemoryEstimate estimateVertexMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options = {});

namespace detail
{
/// The vertex values the gridlets store, per block (same layout as AmrBlock::values), after the
/// transition rule above. On `threads` threads; the result does not depend on them.
std::vector<std::vector<float>> resolveVertexValues(const AmrHierarchy& amr,
  const CellLocator& locator,
  int threads);
} // namespace detail

} // namespace amrdm
