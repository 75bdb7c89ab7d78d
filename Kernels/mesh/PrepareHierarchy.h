// One hierarchy pipeline: every way in (the VTK intake through vtkAMRDualMesh, amrdm-render, the
// benchmarks, scene files, amrdm-devcheck) checks and prepares an AmrHierarchy here, in one
// order, before building a dual mesh:
//   1. AmrHierarchy::validate()   levels, ratios, sizes, overlaps, the domain
//   2. checkNesting()             every refined box aligned with the coarser level's cells and
//                                 inside the coarser level's boxes
//   3. finalizeCellStates()       refined and hidden cells (non-finite values become holes)
//   4. leafValueRange()           the range of the values the field uses
// checkHierarchy() is 1-2 (a description that is not built yet: a scene file being read or
// written), prepareHierarchy() is 1-4. The one log-scale rule is logScaleValue().
#pragma once

#include "mesh/AmrHierarchy.h"
#include "mesh/BoxIndex.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace amrdm
{

/// The AMR's boxes per level as its metadata lists them, loaded here or not (another MPI rank's
/// block, one a reader skipped): inclusive cells in each level's index space, an inverted box
/// (CellBox's default) for an invalid one. Block ids in messages are indices into a level.
using LevelBoxes = std::vector<std::vector<CellBox>>;

/// The hierarchy's own blocks as LevelBoxes (the nesting check's parents when no metadata is
/// known, e.g. for a scene file).
LevelBoxes levelBoxesOf(const AmrHierarchy& h);

/// Throws std::invalid_argument naming the level and block when a box of level L > 0 refines
/// level-(L-1) cells outside level L-1's boxes or, with `aligned`, is not aligned with level
/// L-1's cells (its first cell and its end must be multiples of ratio[L]). `boxes[L]` are level
/// L's boxes; empty or inverted boxes are skipped (validate() reports empty blocks).
void checkNesting(const std::vector<int>& ratio, const LevelBoxes& boxes, bool aligned);

/// Steps 1-2: validate(), then checkNesting(). With `metadata` (the VTK intake's AMR boxes) the
/// boxes must also be aligned, as VTK's AMR requires; without, the blocks' own boxes are the
/// parents and only nesting is checked: a hierarchy made in Kernels (tests, scene files) may
/// split a refined region at any finer cell, which the builder supports. Throws
/// std::invalid_argument.
void checkHierarchy(const AmrHierarchy& h, const LevelBoxes* metadata = nullptr);

/// What preparation found.
struct HierarchySummary
{
  std::int64_t nonFiniteValues = 0;    ///< values that became holes (Points: per block vertices)
  double valueRange[2] = { 0.0, 0.0 }; ///< of the values the field uses; [0, 0] when none
};

/// Steps 1-4 on `threads` threads (0 = all cores; the result does not depend on them). Throws
/// std::invalid_argument on an inconsistent hierarchy, which is then left unchanged.
HierarchySummary prepareHierarchy(AmrHierarchy& h,
  int threads = 1,
  const LevelBoxes* metadata = nullptr);

/// The range of the values the field uses: leaf cells' values, or for point data the corners of
/// leaf cells; [0, 0] when there is none. Needs finalized cell states.
void leafValueRange(const AmrHierarchy& h, int threads, double range[2]);

/// The one log-scale rule: log10(v) for v > 0; a value <= 0 (or NaN) becomes `floor`. The
/// default floor NaN makes it a hole (finalizeCellStates hides it; vtkAMRDualMesh's LogScale);
/// amrdm-render passes a floor below the range of the positive values instead (FieldDefaults).
inline float logScaleValue(double v, double floor = std::numeric_limits<double>::quiet_NaN())
{
  return static_cast<float>(v > 0.0 ? std::log10(v) : floor);
}

} // namespace amrdm
