// Finds the leaf cell that contains a point of a level's lattice, across all levels.
// Host-only: the dual-mesh builder uses it; nothing at render time does.
#pragma once

#include "mesh/AmrHierarchy.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

/// Result of a lookup. `level` is where the containing leaf was found.
struct CellRef
{
  enum Kind : std::uint8_t
  {
    Leaf,    ///< a leaf cell contains the point
    Finer,   ///< the point lies in a cell refined further: a finer leaf owns it
    Missing, ///< outside every block, or in a hidden cell
    Ghost    ///< outside the domain box: a virtual copy of the boundary leaf (mesh/BoundaryLayer.h)
  };
  Kind kind = Missing;
  std::uint8_t sides = 0;  ///< Ghost: which domain faces it lies beyond (BoundaryLayer's code)
  std::int16_t level = -1; ///< at most 31 levels (AmrHierarchy::validate: refinement <= 2^30)
  std::uint32_t block = 0;
  std::int64_t cell = 0; ///< index inside the block
};
// 16 bytes: discovery keeps one per cell of a work item and its halo, per thread.
static_assert(sizeof(CellRef) == 16, "CellRef stays 16 bytes");

/// The last two blocks a run of lookups found: neighbouring lookups (a work item's halo) mostly
/// fall in one of them, and are answered without the bin search. The boxes of one level are
/// disjoint (AmrHierarchy::validate), so a hint never changes a result.
struct BlockHint
{
  int block[2] = { -1, -1 };
};

class CellLocator
{
public:
  explicit CellLocator(const AmrHierarchy& amr);

  /// The block of `level` that contains cell index `c` of that level, or -1.
  int findBlock(int level, const glm::ivec3& c) const;
  int findBlock(int level, const glm::ivec3& c, BlockHint& hint) const;

  /// The cell containing the centre of cell `c` of level `level`: that cell itself if it is a leaf,
  /// else Finer if it is refined, else the covering leaf of a coarser level. `hint` (optional)
  /// remembers the blocks found for the next lookups of a run (BlockHint).
  CellRef locate(int level, const glm::ivec3& c, BlockHint* hint = nullptr) const;

  /// Global id of a cell: offset of its block plus the index inside the block.
  std::int64_t globalId(const CellRef& ref) const
  {
    return this->BlockOffset[ref.block] + ref.cell;
  }
  std::int64_t totalCells() const { return this->BlockOffset.back(); }

  /// Block and in-block index of a global id.
  CellRef fromGlobalId(std::int64_t id) const;
  /// Grid-space (finest units) centre of a cell given by global id.
  glm::dvec3 centre(std::int64_t id) const { return this->centre(this->fromGlobalId(id)); }
  /// Grid-space centre of the cell `ref` names (its block and index; no id lookup).
  glm::dvec3 centre(const CellRef& ref) const;
  /// Scalar value of a cell given by global id.
  float value(std::int64_t id) const;
  /// AmrHierarchy::levelWidth, looked up instead of multiplied out on every call.
  std::int64_t levelWidth(int level) const { return this->Width[static_cast<std::size_t>(level)]; }

private:
  struct LevelGrid
  {
    glm::ivec3 lower{ 0 };               ///< first cell covered, this level's index space
    glm::ivec3 bins{ 0 };                ///< bins per axis
    int binSize = 1;                     ///< cells per bin along each axis
    std::vector<std::uint32_t> binStart; ///< CSR offsets into binBlocks
    std::vector<std::uint32_t> binBlocks;
  };
  const AmrHierarchy& Amr;
  std::vector<LevelGrid> Levels;
  std::vector<std::int64_t> BlockOffset;
  std::vector<std::int64_t> Width; ///< per level, its cell width in finest cells
};

} // namespace amrdm
