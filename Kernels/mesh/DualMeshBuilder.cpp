// The in-memory dual-mesh build. Every leaf cell C of level L looks at its 3x3x3 neighbourhood
// of level-L lattice positions and the leaves that contain them (CellLocator). A dual cell is
// the 2x2x2 sub-neighbourhood; it exists when all 8 positions lie in leaves no finer than L, and
// it is emitted once, by its first level-L corner in bit order. Dual cells whose 8 corners are
// level-L leaves are perfect cubes and go to gridlets; the rest become stitching elements.
// Positions beyond a domain face are ghosts (mesh/BoundaryLayer.h): the dual cells that reach
// them cover the half cells between the hull of the cell centres and the domain faces.
#include "mesh/DualMeshBuilder.h"

#include "accel/CellLocator.h"
#include "mesh/BoundaryLayer.h"
#include "mesh/DualCellDiscovery.h"
#include "mesh/DualMeshBudget.h"
#include "mesh/ElementAssembly.h"
#include "mesh/GridletBuilder.h"
#include "mesh/VertexMeshBuilder.h"
#include "core/ParallelFor.h"
#include "core/ReleaseMemory.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace amrdm
{

namespace
{
using detail::ItemOutput;
using detail::PaddedNeighbourhood;
using detail::processItem;
using detail::WorkItem;

/// Most cells per work item: small enough to balance two to a few dozen threads.
constexpr std::int64_t kCellsPerWorkItem = 1 << 15;
/// Fewest cells per work item, and the items a hierarchy is cut into at least (above that
/// floor): a small hierarchy gets small items, so that each thread's padded neighbourhood (about
/// 22 B per cell of an item) stays small next to its mesh (Enzo: 1.1 MB per thread for a 0.74 MB
/// mesh at 2^15 cells an item). Items depend on the hierarchy only, never on the thread count.
constexpr std::int64_t kMinCellsPerWorkItem = 1 << 12;
constexpr std::int64_t kMinWorkItems = 64;
/// Largest width ratio between touching leaf cells for which the construction is watertight and
/// single-valued (property tests: factor 2 and 4 hold for ratios 2, 3, 4 and for two-level jumps
/// at ratio 2; factors 8, 9 and 16 produce overlapping elements in some configurations).
constexpr std::int64_t kMaxNeighbourWidthRatio = 4;

/// Bytes of the input copy freed between two releaseFreedMemory calls during the gridlet fill.
constexpr std::size_t kTrimBytes = std::size_t(1) << 20;

} // namespace

std::uint64_t availableMemory()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kib * 1024;
    }
  }
  return 0;
}

DualMesh detail::meshFrame(const AmrHierarchy& amr)
{
  DualMesh mesh;
  mesh.sceneOrigin = amr.sceneOrigin;
  mesh.origin = amr.origin;
  mesh.finestSpacing = amr.finestSpacing;
  mesh.domainLower = amr.domainBox().lower;
  mesh.domainUpper = amr.domainBox().upper;
  for (int l = 0; l < amr.numLevels(); ++l)
  {
    mesh.levelWidth.push_back(static_cast<float>(amr.levelWidth(l)));
  }
  return mesh;
}

void DualMeshBuildOptions::validate(const char* gridletUnit) const
{
  if (this->gridletSize < 2 || this->gridletSize > 32)
  {
    throw std::invalid_argument("gridlet size " + std::to_string(this->gridletSize) +
                                " is out of range; expected 2..32 " + gridletUnit + " per axis");
  }
  if (this->bvhLeafSize < 1 || this->bvhLeafSize > 16)
  {
    throw std::invalid_argument(
      "BVH leaf size " + std::to_string(this->bvhLeafSize) + " is out of range; expected 1..16");
  }
}

namespace
{
void validateInput(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
{
  amr.validate();
  options.validate("dual cells");
  for (std::size_t b = 0; b < amr.blocks.size(); ++b)
  {
    if (amr.blocks[b].state.empty())
    {
      throw std::invalid_argument(
        "block " + std::to_string(b) +
        " has no cell states; call AmrHierarchy::finalizeCellStates() before building");
    }
  }
}

/// Work items in a fixed order: blocks, then z-slabs.
std::vector<WorkItem> makeWorkItems(const AmrHierarchy& amr)
{
  std::int64_t cells = 0;
  for (const AmrBlock& block : amr.blocks)
  {
    cells += block.numCells();
  }
  const std::int64_t perItem =
    std::clamp(cells / kMinWorkItems, kMinCellsPerWorkItem, kCellsPerWorkItem);
  std::vector<WorkItem> items;
  for (std::uint32_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    const std::int64_t slab = static_cast<std::int64_t>(block.dims.x) * block.dims.y;
    const int zStep = static_cast<int>(std::max<std::int64_t>(1, perItem / slab));
    for (int z = 0; z < block.dims.z; z += zStep)
    {
      items.push_back({ b, z, std::min(block.dims.z, z + zStep) });
    }
  }
  return items;
}

std::uint64_t resolveMemoryLimit(const DualMeshBuildOptions& options)
{
  return options.memoryLimit > 0 ? options.memoryLimit : availableMemory();
}
} // namespace

DualMeshMemoryEstimate estimateDualMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options)
{
  if (amr.association == FieldAssociation::Points)
  {
    return estimateVertexMeshMemory(amr, options);
  }
  validateInput(amr, options);
  const CellLocator locator(amr);
  const BoundaryLayer boundary(amr, locator);
  const detail::DualCellCensus census = detail::countDualCells(
    amr, boundary, makeWorkItems(amr), options.gridletSize, options.threads, 0);
  return detail::estimateFromCensus(census, options.bvhLeafSize, amr.numLeafCells());
}

DualMeshMemoryEstimate boundDualMeshMemory(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options)
{
  if (amr.association == FieldAssociation::Points)
  {
    return estimateVertexMeshMemory(amr, options); // exact layout, cheap: no separate bound
  }
  validateInput(amr, options);
  const CellLocator locator(amr);
  const BoundaryLayer boundary(amr, locator);
  const detail::DualCellCensus census =
    detail::boundDualCells(amr, boundary, makeWorkItems(amr), options.gridletSize, options.threads);
  return detail::estimateFromCensus(census, options.bvhLeafSize, amr.numLeafCells());
}

namespace
{
DualMesh buildCellMesh(const AmrHierarchy& amr,
  const DualMeshBuildOptions& options,
  const BlockRelease& releaseBlocks)
{
  validateInput(amr, options);
  auto progress = [&](double f)
  {
    if (options.progress)
    {
      options.progress(f);
    }
  };
  const std::uint64_t memoryLimit = resolveMemoryLimit(options);
  const CellLocator locator(amr);
  const BoundaryLayer boundary(amr, locator);

  // 1. Work items and the budget, before anything large is allocated (DualMeshBudget.h): when
  // the upper bound from cell states exceeds the limit, the counting pass gives every category
  // at its true size and the build is refused if that exceeds it too. Then discovery.
  const std::vector<WorkItem> items = makeWorkItems(amr);
  const std::int64_t leafCells = amr.numLeafCells(); // a pass over every cell state: once
  std::vector<std::int64_t> itemElements;
  // Bounds from the loosest (every cell an emitter: block sizes only) to the exact count; each
  // runs only when the one before does not fit.
  const auto boundExceeds = [&](bool everyCellEmits)
  {
    return detail::estimateFromCensus(
             detail::boundDualCells(
               amr, boundary, items, options.gridletSize, options.threads, everyCellEmits),
             options.bvhLeafSize,
             leafCells)
             .peak() > memoryLimit;
  };
  if (memoryLimit > 0 && boundExceeds(true) && boundExceeds(false))
  {
    detail::DualCellCensus census = detail::countDualCells(
      amr, boundary, items, options.gridletSize, options.threads, memoryLimit);
    detail::checkBudget(
      detail::estimateFromCensus(census, options.bvhLeafSize, leafCells), memoryLimit, &amr);
    itemElements = std::move(census.itemElements); // reserves the element records exactly
  }
  progress(0.2);
  std::vector<ItemOutput> outputs(items.size());
  const std::vector<glm::ivec3> gridletOrigins = gridletBlockOrigins(amr);
  {
    // One padded neighbourhood per worker (about 22 B per cell of an item), reused from item to
    // item: a fresh one per item paid its allocation, zeroing and first-touch page faults again
    // for every item. Items are still taken in order and each writes only its own output.
    const std::size_t workers = std::min<std::size_t>(
      static_cast<std::size_t>(resolveThreadCount(options.threads)), items.size());
    std::atomic<std::size_t> next{ 0 };
    parallelFor(workers,
      options.threads,
      [&](std::size_t)
      {
        PaddedNeighbourhood pad;
        for (std::size_t i = next++; i < items.size(); i = next++)
        {
          if (!itemElements.empty())
          {
            outputs[i].elements.reserve(static_cast<std::size_t>(itemElements[i]));
          }
          processItem(
            amr, boundary, items[i], gridletOrigins, options.gridletSize, pad, outputs[i]);
        }
      });
  }
  releaseFreedMemory(); // the workers' neighbourhoods, before the elements are assembled
  progress(0.4);
  for (const ItemOutput& o : outputs)
  {
    if (o.worstJump > kMaxNeighbourWidthRatio)
    {
      throw std::invalid_argument(
        "level-" + std::to_string(o.jumpLevel) + " cell (" + std::to_string(o.jumpCell.x) + ", " +
        std::to_string(o.jumpCell.y) + ", " + std::to_string(o.jumpCell.z) + ") touches a level-" +
        std::to_string(o.jumpCoarse) + " leaf " + std::to_string(o.worstJump) +
        " times wider; the dual mesh is only watertight "
        "where touching leaves differ in width by at most a factor of " +
        std::to_string(kMaxNeighbourWidthRatio) +
        " (ratio 2 with at most two levels between neighbours, or ratio 3 or 4 with one)");
    }
  }

  DualMesh mesh = detail::meshFrame(amr);
  DualMeshCounts& counts = mesh.counts;
  counts.leafCells = leafCells;

  // 2. Stitching elements: shared, de-duplicated vertices and per-kind index arrays
  // (ElementAssembly.h; frees the items' element records). Before the gridlets, so that the
  // records are gone when the gridlet scalars (the mesh's largest array) are allocated.
  detail::assembleElements(boundary, outputs, options.threads, mesh);
  // The element records were allocated by the discovery workers, so their pages sit in those
  // threads' malloc arenas, where this thread's allocations cannot reuse them: hand them back.
  releaseFreedMemory();
  progress(0.6);

  // 3. Gridlets from the perfect cubes' pieces (mesh/GridletLayout.h).
  {
    std::size_t numPieces = 0;
    for (const ItemOutput& o : outputs)
    {
      numPieces += o.gridletPieces.size();
    }
    std::vector<GridletPiece> pieces;
    pieces.reserve(numPieces);
    for (ItemOutput& o : outputs)
    {
      pieces.insert(pieces.end(), o.gridletPieces.begin(), o.gridletPieces.end());
      counts.perfectCubes += o.perfectCubes;
      std::vector<GridletPiece>().swap(o.gridletPieces);
    }
    outputs.clear();
    const std::vector<GridletRange> layout = gridletLayout(std::move(pieces));
    releaseFreedMemory(); // the workers' pieces, before the scalars are allocated
    // A caller that handed the input over (buildDualMesh(AmrHierarchy&&)) gets each block's
    // values and states freed as soon as the gridlet fill is past it: the input copy shrinks
    // while the scalars grow, and nothing after this step reads it.
    buildGridlets(amr, locator, layout, options.gridletSize, options.threads, mesh, releaseBlocks);
    counts.gridlets = static_cast<std::int64_t>(mesh.gridlets.size());
  }
  if (counts.gridlets > static_cast<std::int64_t>(kPrimIndexMask))
  {
    throw std::invalid_argument(
      "the dual mesh has " + std::to_string(counts.gridlets) +
      " gridlets; the BVH can address at most 2^29 primitives of one type");
  }
  releaseFreedMemory();
  progress(0.8);

  // 4. BVH over all primitives.
  detail::buildPrimitiveBvh(mesh, options.bvhLeafSize, options.threads);
  progress(1.0);
  return mesh;
}
} // namespace

DualMesh buildDualMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
{
  if (amr.association == FieldAssociation::Points)
  {
    return buildVertexMesh(amr, options); // vertex-centred data: the primal mesh, no dual
  }
  return buildCellMesh(amr, options, nullptr);
}

DualMesh buildDualMesh(AmrHierarchy&& amr, const DualMeshBuildOptions& options)
{
  if (amr.association == FieldAssociation::Points)
  {
    return buildVertexMesh(amr, options);
  }
  return buildCellMesh(amr,
    options,
    [&amr, unreturned = std::size_t(0)](const std::vector<std::uint32_t>& blocks) mutable
    {
      for (const std::uint32_t b : blocks)
      {
        AmrBlock& block = amr.blocks[b];
        unreturned += block.values.capacity() * sizeof(float) + block.state.capacity();
        std::vector<float>().swap(block.values);
        std::vector<std::uint8_t>().swap(block.state);
      }
      // Small blocks live inside the heap, whose free pages go back to the system only when
      // trimmed: once per kTrimBytes freed, so that trimming stays a small part of the fill.
      if (unreturned >= kTrimBytes)
      {
        releaseFreedMemory();
        unreturned = 0;
      }
    });
}

} // namespace amrdm
