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
#include "mesh/GridletBuilder.h"
#include "core/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
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

/// Cells per work item: small enough to balance two to a few dozen threads.
constexpr std::int64_t kCellsPerWorkItem = 1 << 15;
/// Largest width ratio between touching leaf cells for which the construction is watertight and
/// single-valued (property tests: factor 2 and 4 hold for ratios 2, 3, 4 and for two-level jumps
/// at ratio 2; factors 8, 9 and 16 produce overlapping elements in some configurations).
constexpr std::int64_t kMaxNeighbourWidthRatio = 4;

/// The largest float <= x and the smallest float >= x, per axis (conservative boxes).
glm::vec3 floatBelow(const glm::dvec3& x)
{
  glm::vec3 f(x);
  for (int d = 0; d < 3; ++d)
  {
    if (double(f[d]) > x[d])
    {
      f[d] = std::nextafter(f[d], -std::numeric_limits<float>::infinity());
    }
  }
  return f;
}
glm::vec3 floatAbove(const glm::dvec3& x)
{
  glm::vec3 f(x);
  for (int d = 0; d < 3; ++d)
  {
    if (double(f[d]) < x[d])
    {
      f[d] = std::nextafter(f[d], std::numeric_limits<float>::infinity());
    }
  }
  return f;
}

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

namespace
{
void validateInput(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
{
  amr.validate();
  if (options.gridletSize < 2 || options.gridletSize > 32)
  {
    throw std::invalid_argument("gridlet size " + std::to_string(options.gridletSize) +
                                " is out of range; expected 2..32 dual cells per axis");
  }
  if (options.bvhLeafSize < 1 || options.bvhLeafSize > 16)
  {
    throw std::invalid_argument(
      "BVH leaf size " + std::to_string(options.bvhLeafSize) + " is out of range; expected 1..16");
  }
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
  std::vector<WorkItem> items;
  for (std::uint32_t b = 0; b < amr.blocks.size(); ++b)
  {
    const AmrBlock& block = amr.blocks[b];
    const std::int64_t slab = static_cast<std::int64_t>(block.dims.x) * block.dims.y;
    const int zStep = static_cast<int>(std::max<std::int64_t>(1, kCellsPerWorkItem / slab));
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
  validateInput(amr, options);
  const CellLocator locator(amr);
  const BoundaryLayer boundary(amr, locator);
  const detail::DualCellCensus census =
    detail::boundDualCells(amr, boundary, makeWorkItems(amr), options.gridletSize, options.threads);
  return detail::estimateFromCensus(census, options.bvhLeafSize, amr.numLeafCells());
}

DualMesh buildDualMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
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
  std::vector<std::int64_t> itemElements;
  if (memoryLimit > 0 &&
      detail::estimateFromCensus(
        detail::boundDualCells(amr, boundary, items, options.gridletSize, options.threads),
        options.bvhLeafSize,
        amr.numLeafCells())
          .peak() > memoryLimit)
  {
    detail::DualCellCensus census = detail::countDualCells(
      amr, boundary, items, options.gridletSize, options.threads, memoryLimit);
    detail::checkBudget(
      detail::estimateFromCensus(census, options.bvhLeafSize, amr.numLeafCells()), memoryLimit);
    itemElements = std::move(census.itemElements); // reserves the element records exactly
  }
  progress(0.2);
  std::vector<ItemOutput> outputs(items.size());
  parallelFor(items.size(),
    options.threads,
    [&](std::size_t i)
    {
      PaddedNeighbourhood pad; // about 24 B per cell of the item, freed with it
      if (!itemElements.empty())
      {
        outputs[i].elements.reserve(static_cast<std::size_t>(itemElements[i]));
      }
      processItem(amr, boundary, items[i], pad, outputs[i]);
    });
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
  DualMeshCounts& counts = mesh.counts;
  counts.leafCells = amr.numLeafCells();

  // 2. Gridlets from the perfect cubes.
  {
    std::vector<PerfectCubeRun> runs;
    std::size_t numRuns = 0;
    for (const ItemOutput& o : outputs)
    {
      numRuns += o.cubes.size();
    }
    runs.reserve(numRuns);
    for (ItemOutput& o : outputs)
    {
      runs.insert(runs.end(), o.cubes.begin(), o.cubes.end());
      std::vector<PerfectCubeRun>().swap(o.cubes);
    }
    buildGridlets(amr, locator, runs, options.gridletSize, options.threads, mesh);
    for (const PerfectCubeRun& r : runs)
    {
      counts.perfectCubes += r.length;
    }
    counts.gridlets = static_cast<std::int64_t>(mesh.gridlets.size());
  }
  progress(0.6);

  // 3. Stitching elements: shared, de-duplicated vertices and per-type index arrays. Vertices
  // are the distinct corner cells in global-id order, found through a dense id -> vertex map
  // (4 B per AMR cell, freed at the end of this step); the index arrays are filled per work
  // item in parallel, in work-item order.
  {
    constexpr std::uint32_t kUnused = ~std::uint32_t(0);
    std::vector<std::uint32_t> vertexOf(static_cast<std::size_t>(locator.totalCells()), kUnused);
    std::int64_t numIndices[kElementKindCount] = {};
    std::vector<std::array<std::int64_t, kElementKindCount>> itemStart(outputs.size());
    std::vector<std::int64_t> ghosts; // boundary-layer ghost ids; their vertices follow the cells'
    for (std::size_t i = 0; i < outputs.size(); ++i)
    {
      const ItemOutput& o = outputs[i];
      counts.dropped += o.dropped;
      for (int k = 0; k < kElementKindCount; ++k)
      {
        itemStart[i][static_cast<std::size_t>(k)] = numIndices[k];
      }
      for (const ClassifiedElement& e : o.elements)
      {
        const int kind = primElementKind(std::uint32_t(e.type));
        if (!isElementPrimType(std::uint32_t(e.type)) || e.numCorners != elementCorners(kind))
        {
          throw std::invalid_argument(
            "a dual cell was classified as primitive type " + std::to_string(e.type) + " with " +
            std::to_string(e.numCorners) + " corners; expected a stitching-element kind of " +
            "mesh/ElementList.h (" + elementKindNames() + ") with its number of corners");
        }
        numIndices[kind] += e.numCorners;
        counts.degenerateHexes += e.degenerateHex ? 1 : 0;
        for (int v = 0; v < e.numCorners; ++v)
        {
          if (boundary.isGhost(e.corner[v]))
          {
            ghosts.push_back(e.corner[v]);
          }
          else
          {
            vertexOf[static_cast<std::size_t>(e.corner[v])] = 0;
          }
        }
      }
    }
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    std::vector<std::int64_t> ids;
    for (std::size_t id = 0; id < vertexOf.size(); ++id)
    {
      if (vertexOf[id] != kUnused)
      {
        if (ids.size() >= kPrimIndexMask)
        {
          throw std::invalid_argument("the dual mesh needs more stitching vertices than "
                                      "supported (2^29)");
        }
        vertexOf[id] = static_cast<std::uint32_t>(ids.size());
        ids.push_back(static_cast<std::int64_t>(id));
      }
    }
    const std::size_t firstGhost = ids.size();
    if (firstGhost + ghosts.size() > kPrimIndexMask)
    {
      throw std::invalid_argument(
        "the dual mesh needs more stitching vertices than supported (2^29)");
    }
    ids.insert(ids.end(), ghosts.begin(), ghosts.end());
    auto vertexIndex = [&](std::int64_t id)
    {
      if (!boundary.isGhost(id))
      {
        return vertexOf[static_cast<std::size_t>(id)];
      }
      const auto it = std::lower_bound(ghosts.begin(), ghosts.end(), id);
      return static_cast<std::uint32_t>(firstGhost + static_cast<std::size_t>(it - ghosts.begin()));
    };
    mesh.vertices.resize(ids.size());
    parallelFor(ids.size(),
      options.threads,
      [&](std::size_t i)
      {
        // Twice a cell centre is an integer (within +-2^31 after validate()), and so is a
        // ghost's on the domain faces: exact.
        const glm::dvec3 p2 = 2.0 * boundary.centre(ids[i]);
        mesh.vertices[i] = ElementVertex{ glm::ivec3(glm::round(p2)), boundary.value(ids[i]) };
      });
    for (int k = 0; k < kElementKindCount; ++k)
    {
      mesh.elementIndices[k].resize(static_cast<std::size_t>(numIndices[k]));
    }
    parallelFor(outputs.size(),
      options.threads,
      [&](std::size_t i)
      {
        std::array<std::int64_t, kElementKindCount> next = itemStart[i];
        for (const ClassifiedElement& e : outputs[i].elements)
        {
          const auto k = static_cast<std::size_t>(primElementKind(std::uint32_t(e.type)));
          std::uint32_t* out = mesh.elementIndices[k].data() + next[k];
          for (int v = 0; v < e.numCorners; ++v)
          {
            out[v] = vertexIndex(e.corner[v]);
          }
          next[k] += e.numCorners;
        }
      });
    counts.vertices = static_cast<std::int64_t>(mesh.vertices.size());
    for (int k = -1; k < kElementKindCount; ++k) // -1: the gridlets
    {
      const std::int64_t n = k < 0 ? counts.gridlets : (counts.elements(k) = mesh.numElements(k));
      if (n > static_cast<std::int64_t>(kPrimIndexMask))
      {
        throw std::invalid_argument("the dual mesh has " + std::to_string(n) + " " +
                                    (k < 0 ? "gridlet" : elementKindName(k)) +
                                    "s; the BVH can address at most 2^29 primitives of one type");
      }
    }
  }
  outputs.clear();
  progress(0.8);

  // 4. BVH over all primitives.
  {
    // Boxes are exact in double and rounded outwards to float, so that they contain every
    // point their primitive claims even where grid coordinates exceed float's 2^24.
    std::vector<glm::vec3> lo, hi;
    std::vector<std::uint32_t> refs;
    const std::size_t numPrims =
      mesh.gridlets.size() + static_cast<std::size_t>(counts.totalElements());
    lo.reserve(numPrims);
    hi.reserve(numPrims);
    refs.reserve(numPrims);
    auto addBox = [&](const glm::dvec3& a, const glm::dvec3& b, std::uint32_t ref)
    {
      lo.push_back(floatBelow(a));
      hi.push_back(floatAbove(b));
      refs.push_back(ref);
    };
    for (std::uint32_t g = 0; g < mesh.gridlets.size(); ++g)
    {
      glm::dvec3 a, b; // as the sampler, cut at the domain faces
      gridletGridBox(mesh, mesh.gridlets[g], a, b);
      addBox(a, b, makePrimRef(PrimGridlet, g));
    }
    for (int k = 0; k < kElementKindCount; ++k)
    {
      const int n = elementCorners(k);
      const std::vector<std::uint32_t>& indices = mesh.elementIndices[k];
      for (std::int64_t e = 0; e < mesh.numElements(k); ++e)
      {
        glm::ivec3 a = mesh.vertices[indices[e * n]].pos2, b = a;
        for (int v = 1; v < n; ++v)
        {
          const glm::ivec3 p = mesh.vertices[indices[e * n + v]].pos2;
          a = glm::min(a, p);
          b = glm::max(b, p);
        }
        addBox(0.5 * glm::dvec3(a),
          0.5 * glm::dvec3(b),
          makePrimRef(elementPrimType(k), static_cast<std::uint32_t>(e)));
      }
    }
    mesh.bvh = buildBvh(lo, hi, refs, options.bvhLeafSize, options.threads);
    mesh.validate();
  }
  progress(1.0);
  return mesh;
}

} // namespace amrdm
