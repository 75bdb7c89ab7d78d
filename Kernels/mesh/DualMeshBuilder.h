// Builds the dual mesh of an AMR hierarchy in memory: one dual cell per 2x2x2 neighbourhood of
// leaf-cell centres, perfect cubes clustered into gridlets, the rest kept as stitching elements
// (tets, pyramids, wedges, hexes), and a BVH over both. Host code; parallel and deterministic.
#pragma once

#include "core/ParameterTable.h"
#include "mesh/AmrHierarchy.h"
#include "mesh/DualMesh.h"
#include "mesh/DualMeshBudget.h"

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace amrdm
{

struct DualMeshBuildOptions
{
  /// Gridlets hold up to G^3 dual cells ((G+1)^3 scalars). 2..32, default 8 (the paper's value).
  int gridletSize = int(param::GridletSize.defaultValue);
  /// Worker threads; 0 = all cores. The output does not depend on it.
  int threads = int(param::NumberOfThreads.defaultValue);
  /// Most primitives per BVH leaf, 1..16 (param::BVHLeafSize). Fewer nodes and culling ranges
  /// per primitive as it grows; on the real sets 8 costs no speed against 4 (docs/BENCHMARKS.md).
  int bvhLeafSize = int(param::BVHLeafSize.defaultValue);
  /// Largest number of bytes the build may allocate (temporaries and the mesh); 0 = the
  /// physical memory available now. Checked before anything large is allocated: when
  /// boundDualMeshMemory()'s peak exceeds it, against estimateDualMeshMemory()'s (a counting
  /// pass); exceeding that throws std::length_error with the estimate by category, the limit
  /// and about how many leaf cells would fit.
  std::uint64_t memoryLimit = 0;
  /// Optional progress callback, called with a fraction in [0, 1] from the calling thread.
  std::function<void(double)> progress;

  /// Throws std::invalid_argument, naming the value and the range expected, when gridletSize
  /// is outside 2..32 (`gridletUnit`s per axis: "dual cells", or "cells" for point data) or
  /// bvhLeafSize outside 1..16. Both builders (cell and vertex-centred data) check with it.
  void validate(const char* gridletUnit) const;
};

namespace detail
{
/// A mesh holding the hierarchy's frame and nothing else (scene origin, origin, finest spacing,
/// domain box, level widths): where both builders, of cell and of vertex-centred data, start.
DualMesh meshFrame(const AmrHierarchy& amr);
} // namespace detail

/// A dual cell as found by the construction: its 8 corners as global cell ids (see CellLocator),
/// in bit order (corner k sits at offset (k&1, (k>>1)&1, (k>>2)&1)).
struct DualCellCorners
{
  std::int64_t id[8];
};

/// Eight global cell ids (ghosts included) of 40 bits each: 40 B instead of 64 in every element
/// record, a temporary of the build that DualMeshBudget counts as sizeof(ClassifiedElement).
class PackedCellIds
{
public:
  /// Ids at or above this do not fit (2^40, a trillion cells).
  static constexpr std::int64_t kLimit = std::int64_t(1) << 40;
  std::int64_t operator[](int v) const
  {
    return std::int64_t(this->Low[v]) | (std::int64_t(this->High[v]) << 32);
  }
  /// Throws std::invalid_argument when id is negative or not below kLimit.
  void set(int v, std::int64_t id)
  {
    if (id < 0 || id >= kLimit)
    {
      throw std::invalid_argument("global cell id " + std::to_string(id) +
                                  " of a stitching-element corner; expected 0 <= id < 2^40");
    }
    this->Low[v] = static_cast<std::uint32_t>(id);
    this->High[v] = static_cast<std::uint8_t>(id >> 32);
  }

private:
  std::uint32_t Low[8];
  std::uint8_t High[8];
};

/// How one non-perfect dual cell is stored (44 B: the build keeps one per stitching element
/// until the index arrays are written).
struct ClassifiedElement
{
  PackedCellIds corner;        ///< global cell ids in VTK corner order of `type`
  std::int8_t type = -1;       ///< an element kind's PrimType (mesh/ElementList.h), -1 dropped
  std::uint8_t numCorners = 0; ///< 4 to 8
  bool degenerateHex = false;  ///< a hex with repeated corners
};
static_assert(sizeof(ClassifiedElement) == 44, "element records stay 44 bytes");

/// Classifies a dual cell by which corners coincide: 8 distinct -> hex; a face collapsed to a
/// point -> pyramid (or tet when also one base edge collapsed); two opposite edges of one face
/// collapsed -> wedge; fewer than 4 distinct or a flat shape -> dropped; anything else -> a hex
/// with repeated corners (the degenerate trilinear map is still the dual-mesh interpolant).
/// `position[k]` is corner k's grid-space position, in the ids' order (for the flatness test).
ClassifiedElement classifyDualCell(const DualCellCorners& cell, const glm::dvec3 (&position)[8]);

/// Physical memory available to a new allocation now (Linux: MemAvailable), 0 if unknown.
std::uint64_t availableMemory();

/// What buildDualMesh(amr, options) will allocate, by category (DualMeshBudget.h): one counting
/// pass over dual-cell discovery, no large allocation. Throws as buildDualMesh on invalid input.
DualMeshMemoryEstimate estimateDualMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options = {});

/// An upper bound of estimateDualMeshMemory() from cell states alone (no discovery): the build
/// compares it with the limit first and runs the counting pass only when it does not fit.
DualMeshMemoryEstimate boundDualMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options = {});

/// Builds everything. Throws std::invalid_argument on invalid input (see AmrHierarchy::validate)
/// and when cell states were not finalized. A hierarchy of point data (FieldAssociation::Points)
/// is built by buildVertexMesh() (mesh/VertexMeshBuilder.h), as are its memory estimates.
DualMesh buildDualMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options = {});
/// The same build of a hierarchy handed over: its blocks' values and cell states (the build's
/// largest input, 5 B per AMR cell) are freed block by block during the gridlet fill, each once
/// no gridlet still to be filled reads it (the elements are assembled before), so the copy
/// shrinks while the gridlet scalars grow; `amr` keeps its geometry, not its field.
DualMesh buildDualMesh(AmrHierarchy&& amr, const DualMeshBuildOptions& options = {});

} // namespace amrdm
