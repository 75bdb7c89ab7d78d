// The VTK-free description of a block-structured AMR hierarchy that the dual-mesh builder reads.
// The Mapper fills it from a vtkOverlappingAMR; tests fill it directly.
//
// Conventions (they cause bugs when forgotten):
// - Level 0 is the coarsest level. ratio[L] is the refinement from level L-1 to L (ratio[0] = 1).
// - A block's `lower` is the index of its first cell in *its own level's* index space, relative to
//   the hierarchy origin; cell (i, j, k) of level L covers [i, i+1) * width(L) finest-level units.
// - Integer "finest units" are the grid space of the dual mesh:
//   world = sceneOrigin + origin + spacing * grid. Renderers and every float position work in the
//   scene frame, world - sceneOrigin (double), so a large world offset costs no precision: the
//   VTK intake puts the whole AMR origin into sceneOrigin (origin = 0).
// - Grid coordinates are integers within +-2^30 finest cells per axis (validate() refuses more);
//   stitching vertices store twice their grid position as int32 (cell centres are half-integers).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace amrdm
{

/// State of one AMR cell.
enum CellState : std::uint8_t
{
  CellLeaf = 0,    ///< visible leaf cell: becomes a dual-mesh vertex
  CellRefined = 1, ///< covered by a finer level
  CellHidden = 2   ///< blanked, a ghost copy, or a non-finite value: a hole in the field
};

/// Where the scalars of a hierarchy live: one per cell (the dual mesh joins the cell centres) or
/// one per vertex (vertex-centred / point data: each level's cells are trilinear over their own
/// corners, mesh/VertexMeshBuilder.h).
enum class FieldAssociation : std::uint8_t
{
  Cells = 0,
  Points = 1
};

/// One box of cells on one level.
struct AmrBlock
{
  int level = 0;
  glm::ivec3 lower{ 0 };           ///< first cell, in this level's index space
  glm::ivec3 dims{ 0 };            ///< cells per axis
  std::vector<float> values;       ///< one scalar per cell, or per vertex ((dims+1)^3), x fastest
  std::vector<std::uint8_t> state; ///< CellState per cell; empty = "compute from coverage"

  std::int64_t numCells() const { return static_cast<std::int64_t>(dims.x) * dims.y * dims.z; }
  std::int64_t numPoints() const
  {
    return static_cast<std::int64_t>(dims.x + 1) * (dims.y + 1) * (dims.z + 1);
  }
  /// Index of vertex v (this level's index space; lower..lower+dims) in `values` (Points).
  std::int64_t pointIndex(const glm::ivec3& v) const
  {
    const glm::ivec3 l = v - lower;
    return (static_cast<std::int64_t>(l.z) * (dims.y + 1) + l.y) * (dims.x + 1) + l.x;
  }
  bool contains(const glm::ivec3& c) const
  {
    return c.x >= lower.x && c.y >= lower.y && c.z >= lower.z && c.x < lower.x + dims.x &&
           c.y < lower.y + dims.y && c.z < lower.z + dims.z;
  }
  std::int64_t cellIndex(const glm::ivec3& c) const
  {
    const glm::ivec3 l = c - lower;
    return (static_cast<std::int64_t>(l.z) * dims.y + l.y) * dims.x + l.x;
  }
};

/// Largest |grid coordinate| (finest cells) a block may reach on any axis: doubled cell centres
/// must fit in int32 (stitching vertices) and lattice positions +-1 in int.
constexpr std::int64_t kMaxGridCoordinate = std::int64_t(1) << 30;

/// An axis-aligned box of grid space (finest units), [lower, upper) per axis.
struct GridBox
{
  glm::ivec3 lower{ 0 };
  glm::ivec3 upper{ 0 };

  bool empty() const
  {
    return this->upper.x <= this->lower.x || this->upper.y <= this->lower.y ||
           this->upper.z <= this->lower.z;
  }
};

/// A whole hierarchy. Call validate() then finalizeCellStates() before building.
struct AmrHierarchy
{
  std::vector<int> ratio;          ///< per level; ratio[0] = 1
  std::vector<AmrBlock> blocks;    ///< any order; the builder sorts nothing in place
  glm::dvec3 sceneOrigin{ 0.0 };   ///< world position of the scene frame's zero (double)
  glm::dvec3 origin{ 0.0 };        ///< scene-frame position of grid point 0
  glm::dvec3 finestSpacing{ 1.0 }; ///< world size of one finest-level cell, per axis
  /// The whole domain (grid space). Its faces get the dual mesh's clamped boundary layer; faces
  /// of a part of it (an MPI rank's region) do not. Empty (the default) = domainBox()'s default.
  GridBox domain;
  /// Cells (default): `values` holds one scalar per cell. Points: one per vertex.
  FieldAssociation association = FieldAssociation::Cells;

  int numLevels() const { return static_cast<int>(this->ratio.size()); }

  /// Width of a level-L cell in finest units (product of the finer ratios).
  std::int64_t levelWidth(int level) const;

  /// Throws std::invalid_argument with a message that names the block, level and the problem:
  /// no levels, ratio < 2, a block on an unknown level, empty or negative dims, a block reaching
  /// beyond +-2^30 finest cells (kMaxGridCoordinate), value/state arrays of the wrong size (one
  /// value per cell, or per vertex for FieldAssociation::Points), two
  /// blocks of one level that overlap, a non-empty `domain` whose faces are not on level-0 cell
  /// faces or that does not contain every block.
  void validate() const;

  /// Marks cells covered by a finer block as CellRefined where `state` was empty, then marks
  /// non-finite values as CellHidden (Points: every cell with a non-finite corner). Returns how
  /// many non-finite values were found (Points: vertices of this block). Per block
  /// on `threads` threads (1 by default, 0 = all cores); the result does not depend on them.
  std::int64_t finalizeCellStates(int threads = 1);

  /// `domain`, or when it is empty the bounding box of all blocks rounded outwards to level-0
  /// cells (for a full hierarchy: the bounding box of level 0). A partial hierarchy (one region
  /// of a distributed domain) must set `domain` to the whole domain.
  GridBox domainBox() const;

  /// Visible leaf cells over all blocks.
  std::int64_t numLeafCells() const;
};

/// Floor division for possibly negative integers.
inline int floorDiv(int a, int b)
{
  const int q = a / b;
  return (a % b != 0 && ((a < 0) != (b < 0))) ? q - 1 : q;
}

} // namespace amrdm
