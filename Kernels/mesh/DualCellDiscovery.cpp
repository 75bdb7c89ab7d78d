// See DualCellDiscovery.h.
#include "mesh/DualCellDiscovery.h"

#include <algorithm>
#include <array>

namespace amrdm
{
namespace detail
{

void PaddedNeighbourhood::summarise()
{
  // Three passes of byte ANDs each (x, then y, then z neighbours), instead of 26 scattered loads
  // per cell; entries whose neighbours fall outside the padded box are never read.
  const std::int64_t n = static_cast<std::int64_t>(this->sameLevel.size());
  const std::int64_t sy = this->dims.x, sz = sy * this->dims.y;
  const std::uint8_t* s = this->sameLevel.data();
  this->upperOctant.resize(std::size_t(n)); // scratch: only entries written below are read
  this->neighbourhood.resize(std::size_t(n));
  std::vector<std::uint8_t>& a = this->work[0];
  std::vector<std::uint8_t>& b = this->work[1];
  std::vector<std::uint8_t>& a2 = this->work[2];
  std::vector<std::uint8_t>& b2 = this->work[3];
  for (std::vector<std::uint8_t>& w : this->work)
  {
    w.resize(std::size_t(n));
  }
  for (std::int64_t i = 1; i + 1 < n; ++i)
  {
    a[i] = s[i] & s[i + 1];            // x: {0, 1}
    b[i] = s[i - 1] & s[i] & s[i + 1]; // x: {-1, 0, 1}
  }
  for (std::int64_t i = sy; i + sy < n; ++i)
  {
    a2[i] = a[i] & a[i + sy];
    b2[i] = b[i - sy] & b[i] & b[i + sy];
  }
  for (std::int64_t i = sz; i + sz < n; ++i)
  {
    this->upperOctant[i] = a2[i] & a2[i + sz];
    this->neighbourhood[i] = b2[i - sz] & b2[i] & b2[i + sz];
  }
}

void processItem(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const WorkItem& item,
  const std::vector<glm::ivec3>& gridletOrigins,
  int gridletSize,
  PaddedNeighbourhood& pad,
  ItemOutput& out)
{
  const AmrBlock& block = amr.blocks[item.block];
  const int L = block.level;
  const glm::ivec3 d = block.dims;
  pad.fill(block, item.block, boundary, item.zBegin, item.zEnd);
  // Lower corners of the item's cubes: its cells, or one below them (boundary cubes).
  pad.pieces.begin(L,
    gridletOrigins[static_cast<std::size_t>(L)],
    gridletSize,
    block.lower + glm::ivec3(-1, -1, item.zBegin - 1),
    block.lower + glm::ivec3(d.x - 1, d.y - 1, item.zEnd - 1));
  // Offsets of the 27 neighbours (dx, dy, dz) in {-1, 0, 1}^3, bit order within {0, 1}^3 first
  // (entry k < 8 is corner k of the dual cell whose lower corner is the cell itself).
  std::int64_t offset[27];
  {
    const std::int64_t sx = 1, sy = pad.dims.x, sz = sy * pad.dims.y;
    int n = 0;
    for (int k = 0; k < 8; ++k)
    {
      offset[n++] = (k & 1) * sx + ((k >> 1) & 1) * sy + ((k >> 2) & 1) * sz;
    }
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
        {
          if (dx < 0 || dy < 0 || dz < 0)
          {
            offset[n++] = dx * sx + dy * sy + dz * sz;
          }
        }
  }
  // Ghosts (beyond a domain face) are never same-level leaves: no perfect cube has one.
  auto sameLevelLeaf = [&](const CellRef& r) { return r.kind == CellRef::Leaf && r.level == L; };
  for (int z = item.zBegin; z < item.zEnd; ++z)
    for (int y = 0; y < d.y; ++y)
    {
      int runStart = -1;
      auto flushRun = [&](int xEnd)
      {
        if (runStart >= 0)
        {
          pad.pieces.addRun(block.lower + glm::ivec3(runStart, y, z), xEnd - runStart);
          runStart = -1;
        }
      };
      for (int x = 0; x < d.x; ++x)
      {
        const std::int64_t at = pad.index(x, y, z - item.zBegin);
        const CellRef* self = pad.refs.data() + at;
        if (self->kind != CellRef::Leaf)
        {
          flushRun(x);
          continue;
        }
        // Perfect cube with lower corner c? (Every corner a same-level leaf; c itself is one.)
        const bool perfect = pad.upperOctant[std::size_t(at)] != 0;
        if (perfect)
        {
          if (runStart < 0)
          {
            runStart = x;
          }
        }
        else
        {
          flushRun(x);
        }
        if (pad.neighbourhood[std::size_t(at)] != 0)
        {
          continue; // all 8 dual cells around c are perfect cubes
        }
        const glm::ivec3 c = block.lower + glm::ivec3(x, y, z);
        for (int k = 0; k < 27; ++k)
        {
          const CellRef& r = self[offset[k]];
          if (r.kind == CellRef::Leaf && r.level < L)
          {
            const std::int64_t jump = amr.levelWidth(r.level) / amr.levelWidth(L);
            if (jump > out.worstJump)
            {
              out.worstJump = jump;
              out.jumpLevel = L;
              out.jumpCoarse = r.level;
              out.jumpCell = c;
            }
          }
        }
        // Stitching elements: the dual cells in which c is corner k0.
        for (int k0 = 0; k0 < 8; ++k0)
        {
          // The dual cell's lower corner is c + i0, i0 in {-1, 0}^3.
          const CellRef* lower = self - offset[k0];
          DualCellCorners corners;
          // A level-L ghost is the copy of a level-L cell that is a corner too (its clamped
          // position), so the first level-L cell corner emits every dual cell exactly once.
          // Corner ids are looked up only for the dual cells this cell emits as elements.
          bool exists = true, emitter = true, perfectCube = true, ghost = false;
          for (int k = 0; k < 8 && exists && emitter; ++k)
          {
            const CellRef& r = lower[offset[k]];
            exists = r.kind == CellRef::Leaf || r.kind == CellRef::Ghost;
            const bool same = sameLevelLeaf(r);
            emitter = !(k < k0 && same);
            ghost = ghost || r.kind == CellRef::Ghost;
            perfectCube = perfectCube && (same || (r.kind == CellRef::Ghost && r.level == L));
          }
          if (!exists || !emitter)
          {
            continue;
          }
          if (perfectCube)
          {
            // Without a ghost it is a run's cube (above). With one, every corner is a level-L
            // cell or the ghost of one: a boundary cube. Its gridlet stores the ghosts' values at
            // the lattice positions beyond the face (GridletBuilder), its box ends at the face,
            // and there its trilinear field is the clamped one an element would give.
            if (ghost)
            {
              const glm::ivec3 i0(-(k0 & 1), -((k0 >> 1) & 1), -((k0 >> 2) & 1));
              pad.pieces.addRun(c + i0, 1);
            }
            continue;
          }
          glm::dvec3 position[8];
          for (int k = 0; k < 8; ++k)
          {
            corners.id[k] = boundary.globalId(lower[offset[k]]);
            position[k] = boundary.centre(lower[offset[k]]);
          }
          ClassifiedElement e = classifyDualCell(corners, position);
          if (e.type < 0)
          {
            ++out.dropped;
            continue;
          }
          out.elements.push_back(e);
        }
      }
      flushRun(d.x);
    }
  out.perfectCubes += pad.pieces.finish(out.gridletPieces);
}

} // namespace detail
} // namespace amrdm
