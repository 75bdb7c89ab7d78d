// Which gridlets the perfect dual cubes make, without keeping the cubes: per level, every
// aligned block of G^3 dual cells that holds at least one perfect cube becomes one gridlet,
// bounded by the range of its cubes' lower corners. Discovery (mesh/DualCellDiscovery.h) hands
// each work item's cubes to an ItemGridletPieces, which keeps one range per aligned block the
// item touches (a piece); gridletLayout unites the pieces of all items into the layout. A piece
// is 40 bytes per gridlet block and item, where a run of cubes was 20 bytes per row of cells
// (advection: 84,044 runs, 1.7 MB, against 4,188 pieces, 0.17 MB). Host code.
#pragma once

#include "mesh/AmrHierarchy.h"

#include <cstdint>
#include <vector>

namespace amrdm
{

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

/// One work item's perfect cubes in one aligned block: the block's key (level, block index) and
/// the range of those cubes' lower corners.
struct GridletPiece
{
  int level;
  glm::ivec3 key; ///< aligned block index per axis (from gridletBlockOrigins)
  glm::ivec3 lo, hi;
};

/// Per level, the lattice position where the aligned blocks of G dual cells a side begin: one
/// cell below the domain's lower faces, so that a boundary cube (lower corner at the ghost
/// position) shares its block with the cubes behind it and no gridlet exceeds G a side.
std::vector<glm::ivec3> gridletBlockOrigins(const AmrHierarchy& amr);

/// Aligned blocks that the lower corners lo..hi (inclusive) of one level touch: the most pieces
/// an item covering them makes (the memory budget's bound and ItemGridletPieces' table).
std::int64_t alignedBlocksTouched(const glm::ivec3& origin,
  int gridletSize,
  const glm::ivec3& lo,
  const glm::ivec3& hi);

/// Collects one work item's perfect cubes into pieces: a table of one range per aligned block
/// the item's lower corners can reach, filled run by run, read out in the layout's order (z, y,
/// x). One per worker, reused from item to item.
class ItemGridletPieces
{
public:
  /// Starts an item of `level` whose cubes' lower corners lie in lo..hi (inclusive).
  void begin(int level, const glm::ivec3& origin, int gridletSize, glm::ivec3 lo, glm::ivec3 hi);
  /// Adds `length` cubes with lower corners lower, lower + (1, 0, 0), ...; they must lie in the
  /// begin() range (std::out_of_range otherwise).
  void addRun(const glm::ivec3& lower, int length);
  /// Appends the item's pieces, in key order, to `out`; returns the number of cubes added.
  std::int64_t finish(std::vector<GridletPiece>& out);

private:
  struct Range
  {
    glm::ivec3 lo, hi;
  };
  int level = 0, size = 1;
  glm::ivec3 origin{ 0 }, first{ 0 }, count{ 0 };
  std::int64_t cubes = 0;
  std::vector<Range> table;
};

/// The gridlet layout (the builder's and the memory budget's): the pieces of one key united, in
/// order of level, then block z, y, x. Consumes `pieces`; the result does not depend on their
/// order.
std::vector<GridletRange> gridletLayout(std::vector<GridletPiece> pieces);

} // namespace amrdm
