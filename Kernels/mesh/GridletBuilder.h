// Clusters perfect dual cubes into gridlets: per level, every aligned block of G^3 dual cells
// that holds at least one perfect cube becomes one gridlet with tight bounds; its (dims+1)^3
// scalars are the level's leaf values, NaN where a vertex is not a leaf of that level.
#pragma once

#include "mesh/AmrHierarchy.h"
#include "accel/CellLocator.h"
#include "mesh/DualMesh.h"

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

/// Fills mesh.gridlets and mesh.gridletScalars (ordered by level, then gridlet z, y, x).
void buildGridlets(const AmrHierarchy& amr,
  const CellLocator& locator,
  const std::vector<PerfectCubeRun>& runs,
  int gridletSize,
  int threads,
  DualMesh& mesh);

} // namespace amrdm
