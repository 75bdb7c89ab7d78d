// See DualMeshBudget.h.
#include "mesh/DualMeshBudget.h"

#include "accel/BvhBuilder.h"
#include "accel/CellLocator.h"
#include "mesh/BoundaryLayer.h"
#include "core/ParallelFor.h"
#include "mesh/DualCellDiscovery.h"
#include "mesh/DualMeshBuilder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bitset>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace amrdm
{

namespace
{
constexpr std::uint64_t kMiB = 1024 * 1024;

/// Gridlets of the shared layout (GridletLayout.h: gridletLayout); returns their number and adds
/// their scalars, (dims+1)^3 each, to `scalars`.
std::int64_t countGridlets(std::vector<GridletPiece> pieces, std::uint64_t& scalars)
{
  const std::vector<GridletRange> layout = gridletLayout(std::move(pieces));
  for (const GridletRange& r : layout)
  {
    scalars += gridletScalarCount(r);
  }
  return static_cast<std::int64_t>(layout.size());
}
/// Throws std::length_error when the counting pass's own buffers exceed the limit.
void checkCensusMemory(std::uint64_t bytes, std::uint64_t limit)
{
  if (limit > 0 && bytes > limit)
  {
    throw std::length_error("counting the dual cells needs about " + std::to_string(bytes / kMiB) +
                            " MiB (a bit per AMR cell and the per-thread neighbourhoods), but "
                            "only " +
                            std::to_string(limit / kMiB) +
                            " MiB are available; use a coarser level limit, a smaller region, or "
                            "a machine with more memory");
  }
}

} // namespace

std::uint64_t DualMeshMemoryEstimate::peak() const
{
  const MemoryReport& m = this->mesh;
  const std::uint64_t gridletBytes = m.gridletScalars + m.gridletHeaders;
  const std::uint64_t elementBytes = m.elementVertices + m.elementIndices;
  const std::uint64_t discovery =
    this->elementRecords + this->gridletPieces + this->workItemScratch;
  // Elements first (the records freed at its end), then the gridlets: the items' pieces are
  // copied into one array (each item's freed once copied), united into the layout, and the
  // gridlets built from it.
  const std::uint64_t elements =
    this->elementRecords + this->gridletPieces + this->vertexMap + elementBytes;
  const std::uint64_t gridlets =
    elementBytes +
    std::max(2 * this->gridletPieces + this->gridletLayout, this->gridletLayout + gridletBytes);
  const std::uint64_t bvh = gridletBytes + elementBytes + this->bvhBuild + m.bvh;
  return std::max(std::max(discovery, gridlets), std::max(elements, bvh));
}

std::string DualMeshMemoryEstimate::toJson() const
{
  std::ostringstream s;
  s << "{\"mesh\": " << this->mesh.toJson() << ", \"gridlets\": " << this->gridlets;
#define AMRDM_ELEMENT_JSON(kind, name, member, ...)                                                \
  s << ", \"" #member "\": " << this->elements[int(ElementKind::kind)];
  AMRDM_ELEMENTS(AMRDM_ELEMENT_JSON)
#undef AMRDM_ELEMENT_JSON
  s << ", \"vertices\": " << this->vertices << ", \"primitives\": " << this->primitives
    << ", \"elementRecords\": " << this->elementRecords
    << ", \"gridletPieces\": " << this->gridletPieces
    << ", \"workItemScratch\": " << this->workItemScratch
    << ", \"gridletLayout\": " << this->gridletLayout << ", \"vertexMap\": " << this->vertexMap
    << ", \"bvhBuild\": " << this->bvhBuild << ", \"peak\": " << this->peak() << "}";
  return s.str();
}

namespace detail
{

DualMeshMemoryEstimate estimateFromCensus(const DualCellCensus& census,
  int leafSize,
  std::int64_t leafCells)
{
  DualMeshMemoryEstimate e;
  MemoryReport& m = e.mesh;
  m.leafCells = leafCells;
  e.gridlets = census.gridlets;
  m.gridletScalars = census.gridletScalars * sizeof(float);
  m.gridletHeaders = static_cast<std::uint64_t>(e.gridlets) * sizeof(GridletHeader);
  std::int64_t elements = 0;
  for (int k = 0; k < kElementKindCount; ++k)
  {
    e.elements[k] = census.elements[k];
    elements += census.elements[k];
    m.elementIndices +=
      static_cast<std::uint64_t>(census.elements[k]) * elementCorners(k) * sizeof(std::uint32_t);
  }
  e.vertices = census.vertices;
  m.elementVertices = static_cast<std::uint64_t>(census.vertices) * sizeof(ElementVertex);
  e.primitives = e.gridlets + elements;
  const double perPrimitive =
    census.upperBound ? 2.0 : kBvhNodesPerPrimitive * 4.0 / double(std::max(1, leafSize));
  const double nodes = e.primitives > 0 ? 1.0 + perPrimitive * double(e.primitives) : 0.0;
  const auto prims = static_cast<std::uint64_t>(e.primitives);
  m.bvh = static_cast<std::uint64_t>(nodes) * sizeof(BvhNode) + prims * sizeof(std::uint32_t);

  e.elementRecords = static_cast<std::uint64_t>(elements) * sizeof(ClassifiedElement);
  e.gridletPieces = static_cast<std::uint64_t>(census.gridletPieces) * sizeof(GridletPiece);
  e.workItemScratch = static_cast<std::uint64_t>(census.scratchCells) *
                      static_cast<std::uint64_t>(census.threads) * sizeof(CellRef);
  e.gridletLayout = static_cast<std::uint64_t>(e.gridlets) * sizeof(GridletRange);
  // The rank bitmap of ElementAssembly.cpp: a 64-bit word and a 4-byte rank per 64 AMR cells.
  e.vertexMap = static_cast<std::uint64_t>((census.totalCells + 63) / 64) *
                  (sizeof(std::uint64_t) + sizeof(std::uint32_t)) +
                static_cast<std::uint64_t>(census.vertices) * sizeof(std::int64_t);
  // The BVH build (accel/BvhBuilder.cpp): its input records (box and reference, permuted in
  // place), the parallel subtrees' own node arrays (each up to twice its nodes while it grows)
  // before they are appended, and the partition scratch: at most one chunk of records
  // (kBvhChunkPrims) per thread, but on one thread the right side of the root's split.
  const std::uint64_t subtrees = 2 * static_cast<std::uint64_t>(nodes) * sizeof(BvhNode);
  const std::uint64_t scratch =
    (census.threads > 1 ? std::min<std::uint64_t>(prims, kBvhChunkPrims) *
                            static_cast<std::uint64_t>(census.threads)
                        : prims) *
    sizeof(BvhPrimBox);
  e.bvhBuild = prims * sizeof(BvhPrimBox) + subtrees + scratch;
  return e;
}

int levelsThatFit(const AmrHierarchy& amr,
  const DualMeshMemoryEstimate& e,
  std::uint64_t limit,
  std::int64_t& leafCells)
{
  // Per level: its leaves, and its visible cells (leaves once the finer levels are cut).
  std::vector<std::int64_t> leaves(static_cast<std::size_t>(amr.numLevels()), 0);
  std::vector<std::int64_t> visible(leaves.size(), 0);
  for (const AmrBlock& block : amr.blocks)
  {
    for (const std::uint8_t s : block.state)
    {
      leaves[static_cast<std::size_t>(block.level)] += s == CellLeaf ? 1 : 0;
      visible[static_cast<std::size_t>(block.level)] += s != CellHidden ? 1 : 0;
    }
  }
  const double perLeaf = double(e.peak()) / double(std::max<std::int64_t>(1, e.mesh.leafCells));
  int fit = 0;
  leafCells = 0;
  std::int64_t coarser = 0; // leaves of the levels above the cut
  for (std::size_t l = 0; l < leaves.size(); ++l)
  {
    const std::int64_t cells = coarser + visible[l];
    if (perLeaf * double(cells) > double(limit))
    {
      break;
    }
    fit = static_cast<int>(l) + 1;
    leafCells = cells;
    coarser += leaves[l];
  }
  return fit;
}

/// Throws std::length_error when the build's estimated peak exceeds the limit: the estimate,
/// the limit, about how many leaf cells would fit and, given the hierarchy, how many levels.
void checkBudget(const DualMeshMemoryEstimate& e, std::uint64_t limit, const AmrHierarchy* amr)
{
  const std::uint64_t peak = e.peak();
  if (limit == 0 || peak <= limit)
  {
    return;
  }
  const MemoryReport& m = e.mesh;
  const double fits = double(m.leafCells) * double(limit) / double(peak);
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  const auto mib = [](std::uint64_t bytes) { return double(bytes) / double(kMiB); };
  s << "building the dual mesh needs about " << mib(peak) << " MiB at its peak (the mesh "
    << mib(m.total()) << " MiB: gridlets " << mib(m.gridletScalars + m.gridletHeaders)
    << ", elements " << mib(m.elementVertices + m.elementIndices) << ", BVH " << mib(m.bvh)
    << "; build buffers at most " << mib(peak - m.total()) << " MiB), but only " << mib(limit)
    << " MiB are available; about " << static_cast<long long>(fits) << " of its " << m.leafCells
    << " leaf cells would fit";
  std::int64_t cut = 0;
  const int levels = amr ? levelsThatFit(*amr, e, limit, cut) : -1;
  if (levels > 0 && levels < amr->numLevels())
  {
    s << "; levels 0.." << levels - 1 << " of " << amr->numLevels() << " (about " << cut
      << " leaf cells) would: load fewer levels (e.g. the reader's maximum level)";
  }
  else if (levels == 0)
  {
    s << "; not even level 0 alone would";
  }
  s << "; or use a smaller region, or a machine with more memory";
  throw std::length_error(s.str());
}

namespace
{
/// Leaf cells of `block` that may emit stitching elements: those with a position among their 26
/// neighbours that is not a leaf of the block's level (a non-leaf, a coarser or a finer leaf, a
/// hole, or a boundary-layer ghost). The mask covers the block and a one-cell halo, the halo
/// resolved through the boundary layer's locator (a same-level neighbour block's leaves do not
/// make a shell cell an emitter), then is dilated by one cell per axis.
std::int64_t emitterBound(const AmrBlock& block, const BoundaryLayer& boundary)
{
  const glm::ivec3 d = block.dims, p = d + 2; // p: padded dims
  const std::int64_t sy = p.x, sz = std::int64_t(p.x) * p.y, n = sz * p.z;
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(n)), grown(mask.size());
  BlockHint hint; // the halo's neighbour blocks
  auto halo = [&](int x, int y, int z)
  {
    const CellRef r = boundary.locate(block.level, block.lower + glm::ivec3(x, y, z), &hint);
    return static_cast<std::uint8_t>(r.kind == CellRef::Leaf && r.level == block.level ? 0 : 1);
  };
  // Rows of the padded box: a block row's cells read straight from its states, the rest (and
  // the row's two ends) through the locator.
  for (int z = -1; z <= d.z; ++z)
    for (int y = -1; y <= d.y; ++y)
    {
      std::uint8_t* row = mask.data() + (z + 1) * sz + (y + 1) * sy;
      if (y < 0 || z < 0 || y >= d.y || z >= d.z)
      {
        for (int x = -1; x <= d.x; ++x)
        {
          row[x + 1] = halo(x, y, z);
        }
        continue;
      }
      const std::uint8_t* state =
        block.state.data() +
        (static_cast<std::size_t>(z) * d.y + static_cast<std::size_t>(y)) * d.x;
      row[0] = halo(-1, y, z);
      for (int x = 0; x < d.x; ++x)
      {
        row[x + 1] = state[x] != CellLeaf ? 1 : 0;
      }
      row[d.x + 1] = halo(d.x, y, z);
    }
  // Dilated by one cell along x, then y, then z, each a flat pass. An entry next to the padded
  // box's side reads across the row (or plane) edge, but only the block's cells are counted
  // below, and each pass combines entries of the same other coordinates, so every block cell's
  // result is exact.
  for (const std::int64_t stride : { std::int64_t(1), sy, sz })
  {
    for (std::int64_t c = stride; c + stride < n; ++c)
    {
      grown[static_cast<std::size_t>(c)] = mask[static_cast<std::size_t>(c - stride)] |
                                           mask[static_cast<std::size_t>(c)] |
                                           mask[static_cast<std::size_t>(c + stride)];
    }
    mask.swap(grown);
  }
  std::int64_t count = 0;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
    {
      const std::uint8_t* row = mask.data() + (z + 1) * sz + (y + 1) * sy + 1;
      const std::uint8_t* state =
        block.state.data() +
        (static_cast<std::size_t>(z) * d.y + static_cast<std::size_t>(y)) * d.x;
      for (int x = 0; x < d.x; ++x)
      {
        count += state[x] == CellLeaf && row[x] ? 1 : 0;
      }
    }
  return count;
}

/// What both censuses start from: the AMR cells, the threads the items run on and the largest
/// padded neighbourhood (cells) of one item.
DualCellCensus newCensus(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const std::vector<WorkItem>& items,
  int threads)
{
  DualCellCensus census;
  census.totalCells = boundary.locator().totalCells();
  census.threads = std::max(1, std::min(resolveThreadCount(threads), int(items.size())));
  for (const WorkItem& item : items)
  {
    const glm::ivec3 d = amr.blocks[item.block].dims;
    census.scratchCells = std::max(
      census.scratchCells, std::int64_t(d.x + 2) * (d.y + 2) * (item.zEnd - item.zBegin + 2));
  }
  return census;
}
} // namespace

DualCellCensus boundDualCells(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const std::vector<WorkItem>& items,
  int gridletSize,
  int threads,
  bool everyCellEmits)
{
  DualCellCensus census = newCensus(amr, boundary, items, threads);
  census.upperBound = true;
  std::vector<std::int64_t> emitters(amr.blocks.size());
  parallelFor(amr.blocks.size(),
    threads,
    [&](std::size_t b)
    {
      const glm::ivec3 d = amr.blocks[b].dims;
      emitters[b] =
        everyCellEmits ? std::int64_t(d.x) * d.y * d.z : emitterBound(amr.blocks[b], boundary);
    });
  const int G = gridletSize;
  const std::uint64_t fullGridlet = std::uint64_t(G + 1) * (G + 1) * (G + 1);
  const std::vector<glm::ivec3> origin = gridletBlockOrigins(amr);
  std::int64_t elements = 0, emitting = 0;
  for (std::size_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    const glm::ivec3 d = block.dims;
    elements += 8 * emitters[b];
    emitting += emitters[b];
    // Aligned blocks from GridletLayout's origin; the cell below the block counts for the
    // boundary cubes whose lower corner lies beyond a domain face.
    const std::int64_t chunks = alignedBlocksTouched(origin[static_cast<std::size_t>(block.level)],
      G,
      block.lower - glm::ivec3(1),
      block.lower + d - glm::ivec3(1));
    census.gridlets += chunks;
    census.gridletScalars += static_cast<std::uint64_t>(chunks) * fullGridlet;
  }
  for (const WorkItem& item : items)
  {
    // An item makes at most one piece per aligned block its cubes' lower corners reach
    // (processItem's range).
    const AmrBlock& block = amr.blocks[item.block];
    census.gridletPieces += alignedBlocksTouched(origin[static_cast<std::size_t>(block.level)],
      G,
      block.lower + glm::ivec3(-1, -1, item.zBegin - 1),
      block.lower + glm::ivec3(block.dims.x - 1, block.dims.y - 1, item.zEnd - 1));
  }
  for (int k = 0; k < kElementKindCount; ++k)
  {
    if (elementCorners(k) == kMaxElementCorners)
    {
      census.elements[k] = elements; // all of the kind with the most corners
      break;
    }
  }
  // Corners are leaves or boundary-layer ghosts; a ghost belongs to a leaf on a domain face (a
  // block shell cell, so an emitter), at most 7 per leaf (3 faces, 3 edges, 1 corner).
  census.vertices = std::min(amr.numLeafCells() + 7 * emitting, kMaxElementCorners * elements);
  return census;
}

/// The counting pass (DualMeshBudget.h): discovery of every item, keeping its gridlet pieces
/// and counting its elements per kind and their distinct corners (a bit per AMR cell); the
/// element records are dropped item by item. Checks its own buffers against `limit` first.
DualCellCensus countDualCells(const AmrHierarchy& amr,
  const BoundaryLayer& boundary,
  const std::vector<WorkItem>& items,
  int gridletSize,
  int threads,
  std::uint64_t limit)
{
  DualCellCensus census = newCensus(amr, boundary, items, threads);
  const std::size_t words = static_cast<std::size_t>((census.totalCells + 63) / 64);
  checkCensusMemory(words * 8 + static_cast<std::uint64_t>(census.scratchCells) *
                                  static_cast<std::uint64_t>(census.threads) * sizeof(CellRef),
    limit);
  std::unique_ptr<std::atomic<std::uint64_t>[]> used(new std::atomic<std::uint64_t>[words]);
  for (std::size_t w = 0; w < words; ++w)
  {
    used[w].store(0, std::memory_order_relaxed);
  }
  const std::vector<glm::ivec3> origins = gridletBlockOrigins(amr);
  std::vector<std::vector<GridletPiece>> pieces(items.size());
  std::vector<std::vector<std::int64_t>> ghosts(items.size()); // ids beyond the bit set
  std::vector<std::array<std::int64_t, kElementKindCount>> counts(items.size());
  census.itemElements.resize(items.size());
  parallelFor(items.size(),
    threads,
    [&](std::size_t i)
    {
      PaddedNeighbourhood pad;
      ItemOutput out;
      processItem(amr, boundary, items[i], origins, gridletSize, pad, out);
      counts[i].fill(0);
      for (const ClassifiedElement& e : out.elements)
      {
        if (isElementPrimType(std::uint32_t(e.type)))
        {
          ++counts[i][static_cast<std::size_t>(primElementKind(std::uint32_t(e.type)))];
        }
        for (int v = 0; v < e.numCorners; ++v)
        {
          if (boundary.isGhost(e.corner[v]))
          {
            ghosts[i].push_back(e.corner[v]);
            continue;
          }
          const auto id = static_cast<std::uint64_t>(e.corner[v]);
          used[id / 64].fetch_or(std::uint64_t(1) << (id % 64), std::memory_order_relaxed);
        }
      }
      census.itemElements[i] = static_cast<std::int64_t>(out.elements.size());
      pieces[i] = std::move(out.gridletPieces);
    });
  std::size_t numPieces = 0;
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    numPieces += pieces[i].size();
    for (int k = 0; k < kElementKindCount; ++k)
    {
      census.elements[k] += counts[i][static_cast<std::size_t>(k)];
    }
  }
  std::vector<GridletPiece> all;
  all.reserve(numPieces);
  for (std::vector<GridletPiece>& p : pieces)
  {
    all.insert(all.end(), p.begin(), p.end());
    std::vector<GridletPiece>().swap(p);
  }
  census.gridletPieces = static_cast<std::int64_t>(all.size());
  census.gridlets = countGridlets(std::move(all), census.gridletScalars);
  for (std::size_t w = 0; w < words; ++w)
  {
    census.vertices += std::bitset<64>(used[w].load(std::memory_order_relaxed)).count();
  }
  std::vector<std::int64_t> allGhosts;
  for (std::vector<std::int64_t>& g : ghosts)
  {
    allGhosts.insert(allGhosts.end(), g.begin(), g.end());
    std::vector<std::int64_t>().swap(g);
  }
  std::sort(allGhosts.begin(), allGhosts.end());
  census.vertices += std::unique(allGhosts.begin(), allGhosts.end()) - allGhosts.begin();
  return census;
}

} // namespace detail
} // namespace amrdm
