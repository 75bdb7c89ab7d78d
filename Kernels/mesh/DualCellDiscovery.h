// Dual-cell discovery for one work item of the dual-mesh build (DualMeshBuilder.cpp): the
// cells of a slab of one block plus a one-cell halo, resolved to their leaves, and the dual
// cells they emit: perfect cubes (runs, for gridlets) and classified stitching elements, those
// of the clamped boundary layer (mesh/BoundaryLayer.h) included. Host code.
#pragma once

#include "mesh/AmrHierarchy.h"
#include "accel/CellLocator.h"
#include "mesh/BoundaryLayer.h"
#include "mesh/DualMeshBuilder.h"
#include "mesh/GridletLayout.h"

#include <cstdint>
#include <vector>

namespace amrdm
{
namespace detail
{

struct WorkItem
{
  std::uint32_t block;
  int zBegin, zEnd;
};

struct ItemOutput
{
  std::vector<ClassifiedElement> elements;
  std::vector<GridletPiece> gridletPieces; ///< the item's perfect cubes, per aligned block
  std::int64_t perfectCubes = 0;
  std::int64_t dropped = 0;
  std::int64_t worstJump = 1;        ///< largest width ratio between touching leaves seen
  int jumpLevel = 0, jumpCoarse = 0; ///< where it was seen (finer and coarser level)
  glm::ivec3 jumpCell{ 0 };
};

/// The cells of a work item plus a one-cell halo, each resolved to the leaf that contains it:
/// cells of the item's block from their state, halo cells outside the block through the
/// CellLocator, once each (a halo cell is a neighbour of up to 9 of the item's cells); halo
/// positions beyond a domain face are ghosts (BoundaryLayer).
struct PaddedNeighbourhood
{
  glm::ivec3 dims{ 0 }; ///< item dims + 2
  std::vector<CellRef> refs;
  /// 1 where refs[i] is a leaf of the block's level: what the perfect-cube tests read, 1 byte
  /// per cell instead of a 16-byte CellRef (an item's bytes stay in the first-level cache).
  std::vector<std::uint8_t> sameLevel;
  /// Per cell, the AND of sameLevel over the cell's upper octant {0, 1}^3 (the perfect cube
  /// with that lower corner) and over its 3^3 neighbourhood (all 8 dual cells around it are
  /// perfect cubes); valid for the item's cells, computed by summarise() in separable passes.
  std::vector<std::uint8_t> upperOctant, neighbourhood;
  std::vector<std::uint8_t> work[4]; ///< summarise()'s intermediate passes (scratch)
  ItemGridletPieces pieces;          ///< the item's perfect cubes, collected per aligned block

  std::int64_t index(int x, int y, int z) const // item-local coordinates, -1..dims-2
  {
    return ((static_cast<std::int64_t>(z) + 1) * this->dims.y + (y + 1)) * this->dims.x + (x + 1);
  }

  void fill(const AmrBlock& block,
    std::uint32_t blockIndex,
    const BoundaryLayer& boundary,
    int zBegin,
    int zEnd)
  {
    const glm::ivec3 d = block.dims;
    this->dims = glm::ivec3(d.x + 2, d.y + 2, zEnd - zBegin + 2);
    this->refs.resize(static_cast<std::size_t>(this->dims.x) * this->dims.y * this->dims.z);
    this->sameLevel.resize(this->refs.size());
    std::size_t i = 0;
    BlockHint hint; // the halo's neighbour blocks
    for (int z = zBegin - 1; z <= zEnd; ++z)
      for (int y = -1; y <= d.y; ++y)
        for (int x = -1; x <= d.x; ++x, ++i)
        {
          CellRef& r = this->refs[i];
          if (x >= 0 && y >= 0 && z >= 0 && x < d.x && y < d.y && z < d.z)
          {
            const std::int64_t cell = (static_cast<std::int64_t>(z) * d.y + y) * d.x + x;
            const std::uint8_t s = block.state[static_cast<std::size_t>(cell)];
            r.kind = s == CellLeaf ? CellRef::Leaf
                                   : (s == CellRefined ? CellRef::Finer : CellRef::Missing);
            r.sides = 0;
            r.level = block.level;
            r.block = blockIndex;
            r.cell = cell;
          }
          else
          {
            r = boundary.locate(block.level, block.lower + glm::ivec3(x, y, z), &hint);
          }
          this->sameLevel[i] = r.kind == CellRef::Leaf && r.level == block.level ? 1 : 0;
        }
    this->summarise();
  }

  /// Fills upperOctant and neighbourhood from sameLevel.
  void summarise();
};

/// Finds the dual cells that `item`'s cells emit (each once, by its first level-L corner that is
/// a cell, not a ghost) and appends them to `out` (perfect cubes as gridlet pieces, on the
/// aligned blocks of `gridletSize` from `gridletOrigins`, gridletBlockOrigins());
/// `pad` is the caller's per-thread scratch.
/// A dual cell with a ghost corner is a boundary cube when every corner is a level-L cell or the
/// ghost of one: it joins the gridlets as a run of length 1 (lower corner beyond the face);
/// otherwise (a level transition on the face) it becomes a stitching element.
void processItem(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const WorkItem& item,
  const std::vector<glm::ivec3>& gridletOrigins,
  int gridletSize,
  PaddedNeighbourhood& pad,
  ItemOutput& out);

} // namespace detail
} // namespace amrdm
