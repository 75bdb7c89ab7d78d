// See VertexMeshBuilder.h.
#include "mesh/VertexMeshBuilder.h"

#include "core/ParallelFor.h"
#include "accel/BvhBuilder.h"
#include "mesh/DualMeshBudget.h"
#include "mesh/ElementAssembly.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace amrdm
{

namespace
{
/// A gridlet of primal cells: cells lo..hi (inclusive) of block `block`'s level.
struct CellRange
{
  std::uint32_t block;
  glm::ivec3 lo, hi;
};

std::string blockText(std::size_t b, const AmrBlock& block)
{
  return "block " + std::to_string(b) + " (level " + std::to_string(block.level) + ")";
}

void validateInput(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
{
  amr.validate();
  if (amr.association != FieldAssociation::Points)
  {
    throw std::invalid_argument("the vertex-centred build needs a hierarchy of point data (one "
                                "value per vertex); this one holds cell data");
  }
  options.validate("cells");
  for (std::size_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    if (block.state.empty())
    {
      throw std::invalid_argument(
        blockText(b, block) +
        " has no cell states; call AmrHierarchy::finalizeCellStates() before building");
    }
  }
}

bool isLeaf(const AmrBlock& block, const glm::ivec3& c)
{
  return block.state[static_cast<std::size_t>(block.cellIndex(c))] == CellLeaf;
}

/// The trilinear interpolant at finest-grid point p of a leaf cell of the finest level coarser
/// than `level` that has one whose closure holds p (from its resolved corner values). False when
/// no coarser leaf touches p.
bool coarserInterpolant(const AmrHierarchy& amr,
  const CellLocator& locator,
  const std::vector<std::vector<float>>& resolved,
  int level,
  const glm::i64vec3& p,
  float& value)
{
  for (int l = level - 1; l >= 0; --l)
  {
    const std::int64_t w = amr.levelWidth(l);
    glm::ivec3 base;
    glm::ivec3 onFace;
    for (int d = 0; d < 3; ++d)
    {
      const std::int64_t q = p[d] >= 0 ? p[d] / w : -((-p[d] + w - 1) / w);
      base[d] = static_cast<int>(q);
      onFace[d] = q * w == p[d] ? 1 : 0;
    }
    for (int k = 0; k < 8; ++k)
    {
      const glm::ivec3 off(k & 1, (k >> 1) & 1, (k >> 2) & 1);
      if (glm::any(glm::greaterThan(off, onFace)))
      {
        continue;
      }
      const glm::ivec3 c = base - off;
      const int b = locator.findBlock(l, c);
      if (b < 0 || !isLeaf(amr.blocks[static_cast<std::size_t>(b)], c))
      {
        continue;
      }
      const AmrBlock& block = amr.blocks[static_cast<std::size_t>(b)];
      const std::vector<float>& v = resolved[static_cast<std::size_t>(b)];
      const glm::dvec3 f = (glm::dvec3(p) - glm::dvec3(c) * double(w)) / double(w);
      double result = 0.0;
      for (int corner = 0; corner < 8; ++corner)
      {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const double weight =
          (o.x ? f.x : 1.0 - f.x) * (o.y ? f.y : 1.0 - f.y) * (o.z ? f.z : 1.0 - f.z);
        result += weight * double(v[static_cast<std::size_t>(block.pointIndex(c + o))]);
      }
      value = static_cast<float>(result);
      return true;
    }
  }
  return false;
}

/// The value of vertex v of `level` when no coarser leaf touches it: the input value of the
/// lowest-numbered block of that level that holds v.
float firstBlockValue(const AmrHierarchy& amr,
  const CellLocator& locator,
  std::size_t self,
  const glm::ivec3& v)
{
  const int level = amr.blocks[self].level;
  std::size_t first = self;
  for (int k = 0; k < 8; ++k)
  {
    const int b = locator.findBlock(level, v - glm::ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    if (b >= 0 && static_cast<std::size_t>(b) < first)
    {
      first = static_cast<std::size_t>(b);
    }
  }
  const AmrBlock& block = amr.blocks[first];
  return block.values[static_cast<std::size_t>(block.pointIndex(v))];
}

/// Marks the vertices of cells lo..hi that are corners of a leaf cell in that range.
void usedVertices(const AmrBlock& block,
  const glm::ivec3& lo,
  const glm::ivec3& hi,
  std::vector<std::uint8_t>& used)
{
  const glm::ivec3 n = hi - lo + 2;
  used.assign(static_cast<std::size_t>(n.x) * n.y * n.z, 0);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
      {
        if (!isLeaf(block, { x, y, z }))
        {
          continue;
        }
        for (int k = 0; k < 8; ++k)
        {
          const glm::ivec3 v = glm::ivec3(x, y, z) - lo + glm::ivec3(k & 1, (k >> 1) & 1, k >> 2);
          used[(static_cast<std::size_t>(v.z) * n.y + v.y) * n.x + v.x] = 1;
        }
      }
}

/// Gridlets for cells lo..hi of block b: the range shrunk to its leaf cells; split in halves
/// along its longest axis while a non-leaf cell in it has all 8 corners on leaf cells of the
/// range (the gridlet would claim it: a NaN corner is what keeps a cell out).
void layoutRange(const AmrBlock& block,
  std::uint32_t b,
  glm::ivec3 lo,
  glm::ivec3 hi,
  std::vector<CellRange>& out)
{
  glm::ivec3 a(std::numeric_limits<int>::max()), c(std::numeric_limits<int>::min());
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
      {
        if (isLeaf(block, { x, y, z }))
        {
          a = glm::min(a, glm::ivec3(x, y, z));
          c = glm::max(c, glm::ivec3(x, y, z));
        }
      }
  if (a.x > c.x)
  {
    return; // no leaf cell
  }
  lo = a;
  hi = c;
  std::vector<std::uint8_t> used;
  usedVertices(block, lo, hi, used);
  const glm::ivec3 n = hi - lo + 2;
  bool claimsEmpty = false;
  for (int z = lo.z; z <= hi.z && !claimsEmpty; ++z)
    for (int y = lo.y; y <= hi.y && !claimsEmpty; ++y)
      for (int x = lo.x; x <= hi.x && !claimsEmpty; ++x)
      {
        if (isLeaf(block, { x, y, z }))
        {
          continue;
        }
        bool all = true;
        for (int k = 0; k < 8 && all; ++k)
        {
          const glm::ivec3 v = glm::ivec3(x, y, z) - lo + glm::ivec3(k & 1, (k >> 1) & 1, k >> 2);
          all = used[(static_cast<std::size_t>(v.z) * n.y + v.y) * n.x + v.x] != 0;
        }
        claimsEmpty = all;
      }
  if (!claimsEmpty)
  {
    out.push_back({ b, lo, hi });
    return;
  }
  const glm::ivec3 extent = hi - lo;
  const int axis =
    extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  glm::ivec3 mid = hi;
  mid[axis] = lo[axis] + extent[axis] / 2;
  layoutRange(block, b, lo, mid, out);
  glm::ivec3 next = lo;
  next[axis] = mid[axis] + 1;
  layoutRange(block, b, next, hi, out);
}

/// The gridlets of every block: aligned G^3 chunks from each block's first cell, in block order.
std::vector<CellRange> vertexGridletLayout(const AmrHierarchy& amr, int G, int threads)
{
  struct Chunk
  {
    std::uint32_t block;
    glm::ivec3 lo;
  };
  std::vector<Chunk> chunks;
  for (std::uint32_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    for (int z = 0; z < block.dims.z; z += G)
      for (int y = 0; y < block.dims.y; y += G)
        for (int x = 0; x < block.dims.x; x += G)
        {
          chunks.push_back({ b, block.lower + glm::ivec3(x, y, z) });
        }
  }
  std::vector<std::vector<CellRange>> parts(chunks.size());
  parallelFor(chunks.size(),
    threads,
    [&](std::size_t i)
    {
      const AmrBlock& block = amr.blocks[chunks[i].block];
      const glm::ivec3 hi = glm::min(chunks[i].lo + (G - 1), block.lower + block.dims - 1);
      layoutRange(block, chunks[i].block, chunks[i].lo, hi, parts[i]);
    });
  std::vector<CellRange> out;
  for (std::vector<CellRange>& p : parts)
  {
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

std::uint64_t rangeScalars(const CellRange& r)
{
  const glm::i64vec3 n = glm::i64vec3(r.hi - r.lo) + std::int64_t(2);
  return static_cast<std::uint64_t>(n.x * n.y * n.z);
}

DualMeshMemoryEstimate estimateFromLayout(const AmrHierarchy& amr,
  const std::vector<CellRange>& layout)
{
  DualMeshMemoryEstimate e;
  MemoryReport& m = e.mesh;
  m.leafCells = amr.numLeafCells();
  e.gridlets = static_cast<std::int64_t>(layout.size());
  e.primitives = e.gridlets;
  for (const CellRange& r : layout)
  {
    m.gridletScalars += rangeScalars(r) * sizeof(float);
  }
  m.gridletHeaders = layout.size() * sizeof(GridletHeader);
  const std::uint64_t prims = layout.size();
  m.bvh = prims * sizeof(std::uint32_t) + 2 * prims * sizeof(BvhNode); // at most 2 nodes each
  for (const AmrBlock& block : amr.blocks)
  {
    e.vertexMap += static_cast<std::uint64_t>(block.numPoints()) * sizeof(float);
  }
  e.gridletLayout = layout.size() * sizeof(CellRange);
  // The BVH build's records (box and reference) and its subtrees' node arrays (each up to
  // twice its nodes while it grows; accel/BvhBuilder.cpp).
  e.bvhBuild = prims * sizeof(BvhPrimBox) + 4 * prims * sizeof(BvhNode);
  return e;
}
} // namespace

namespace detail
{
std::vector<std::vector<float>> resolveVertexValues(const AmrHierarchy& amr,
  const CellLocator& locator,
  int threads)
{
  std::vector<std::vector<float>> resolved(amr.blocks.size());
  for (int level = 0; level < amr.numLevels(); ++level)
  {
    const std::int64_t w = amr.levelWidth(level);
    parallelFor(amr.blocks.size(),
      threads,
      [&](std::size_t b)
      {
        const AmrBlock& block = amr.blocks[b];
        if (block.level != level)
        {
          return;
        }
        std::vector<float>& out = resolved[b];
        out = block.values;
        // Only a block's face vertices can touch a coarser leaf or another block of its level:
        // coarser cells under its interior are refined.
        const glm::ivec3 d = block.dims;
        for (int z = 0; z <= d.z; ++z)
          for (int y = 0; y <= d.y; ++y)
          {
            const bool face = z == 0 || z == d.z || y == 0 || y == d.y;
            for (int x = 0; x <= d.x; x += (face || x == d.x) ? 1 : d.x)
            {
              const glm::ivec3 v = block.lower + glm::ivec3(x, y, z);
              float value;
              if (!coarserInterpolant(amr, locator, resolved, level, glm::i64vec3(v) * w, value))
              {
                value = firstBlockValue(amr, locator, b, v);
              }
              out[static_cast<std::size_t>(block.pointIndex(v))] = value;
            }
          }
      });
  }
  return resolved;
}
} // namespace detail

DualMeshMemoryEstimate estimateVertexMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options)
{
  validateInput(amr, options);
  return estimateFromLayout(amr, vertexGridletLayout(amr, options.gridletSize, options.threads));
}

DualMesh buildVertexMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
{
  validateInput(amr, options);
  auto progress = [&](double f)
  {
    if (options.progress)
    {
      options.progress(f);
    }
  };
  std::vector<CellRange> layout = vertexGridletLayout(amr, options.gridletSize, options.threads);
  const std::uint64_t limit = options.memoryLimit > 0 ? options.memoryLimit : availableMemory();
  detail::checkBudget(estimateFromLayout(amr, layout), limit, &amr);
  progress(0.2);
  const CellLocator locator(amr);
  std::vector<std::vector<float>> values =
    detail::resolveVertexValues(amr, locator, options.threads);
  progress(0.4);

  DualMesh mesh = detail::meshFrame(amr);
  mesh.gridletOrigin = 0.0f; // the gridlet lattice is the cells' corners (DualMesh.h)
  if (layout.size() > static_cast<std::size_t>(kPrimIndexMask))
  {
    throw std::invalid_argument("the vertex mesh has " + std::to_string(layout.size()) +
                                " gridlets; the BVH can address at most 2^29 primitives of one "
                                "type");
  }
  mesh.gridlets.resize(layout.size());
  std::uint64_t offset = 0;
  for (std::size_t g = 0; g < layout.size(); ++g)
  {
    GridletHeader& h = mesh.gridlets[g];
    h.lower = layout[g].lo;
    h.level = amr.blocks[layout[g].block].level;
    h.dims = layout[g].hi - layout[g].lo + 1;
    h.begin = static_cast<std::uint32_t>(offset);
    offset += rangeScalars(layout[g]);
    if (offset > std::numeric_limits<std::uint32_t>::max())
    {
      throw std::invalid_argument("gridlet scalars exceed 2^32 values; use fewer cells");
    }
  }
  mesh.gridletScalars.resize(offset); // uninitialised: every scalar is written below
  parallelFor(layout.size(),
    options.threads,
    [&](std::size_t g)
    {
      const CellRange& r = layout[g];
      const AmrBlock& block = amr.blocks[r.block];
      const std::vector<float>& v = values[r.block];
      std::vector<std::uint8_t> used;
      usedVertices(block, r.lo, r.hi, used);
      float* s = mesh.gridletScalars.data() + mesh.gridlets[g].begin;
      std::size_t i = 0;
      for (int z = r.lo.z; z <= r.hi.z + 1; ++z)
        for (int y = r.lo.y; y <= r.hi.y + 1; ++y)
          for (int x = r.lo.x; x <= r.hi.x + 1; ++x, ++i)
          {
            s[i] = used[i] ? v[static_cast<std::size_t>(block.pointIndex({ x, y, z }))]
                           : std::numeric_limits<float>::quiet_NaN();
          }
    });
  std::vector<std::vector<float>>().swap(values);
  std::vector<CellRange>().swap(layout);
  DualMeshCounts& counts = mesh.counts;
  counts.leafCells = amr.numLeafCells();
  counts.perfectCubes = counts.leafCells; // every leaf cell is a gridlet cell
  counts.gridlets = static_cast<std::int64_t>(mesh.gridlets.size());
  progress(0.7);
  detail::buildPrimitiveBvh(mesh, options.bvhLeafSize, options.threads);
  progress(1.0);
  return mesh;
}

} // namespace amrdm
