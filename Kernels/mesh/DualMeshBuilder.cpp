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
/// Bytes per visible leaf cell the classification pass may need at most before the exact sizes
/// are known: perfect-cube runs, element records and per-item buffers (measured worst cases on
/// the property tests stay below 10 B).
constexpr std::uint64_t kFirstPassBytesPerLeaf = 16;

/// Throws std::length_error when `bytes` exceed the limit.
void checkMemory(std::uint64_t bytes, std::uint64_t limit, const char* what)
{
  if (limit > 0 && bytes > limit)
  {
    throw std::length_error(
      std::string("building the dual mesh needs about ") + std::to_string(bytes / (1024 * 1024)) +
      " MiB for " + what + ", but only " + std::to_string(limit / (1024 * 1024)) +
      " MiB are available; use a coarser level limit, a smaller region, or a machine with more "
      "memory");
  }
}

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

DualMesh buildDualMesh(const AmrHierarchy& amr, const DualMeshBuildOptions& options)
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
  auto progress = [&](double f)
  {
    if (options.progress)
    {
      options.progress(f);
    }
  };
  const std::uint64_t memoryLimit =
    options.memoryLimit > 0 ? options.memoryLimit : availableMemory();
  checkMemory(static_cast<std::uint64_t>(amr.numLeafCells()) * kFirstPassBytesPerLeaf,
    memoryLimit,
    "classifying the dual cells");
  const CellLocator locator(amr);
  const BoundaryLayer boundary(amr, locator);

  // 1. Work items in a fixed order: blocks, then z-slabs.
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
  std::vector<ItemOutput> outputs(items.size());
  parallelFor(items.size(),
    options.threads,
    [&](std::size_t i)
    {
      PaddedNeighbourhood pad; // about 24 B per cell of the item, freed with it
      processItem(amr, boundary, items[i], pad, outputs[i]);
    });
  progress(0.4);
  {
    // Exact sizes of the mesh are known now: check them before allocating it.
    std::uint64_t cubes = 0, elements = 0;
    for (const ItemOutput& o : outputs)
    {
      for (const PerfectCubeRun& r : o.cubes)
      {
        cubes += static_cast<std::uint64_t>(r.length);
      }
      elements += o.elements.size();
    }
    // Gridlet scalars are at most about 2 floats per cube for G >= 2 ((G+1)^3 / G^3 <= 3.4 at
    // G = 2, counted fully); elements need indices, vertices and BVH entries.
    const std::uint64_t gridScale = options.gridletSize == 2 ? 4 : 2;
    // Plus the id -> vertex map of step 3 (4 B per AMR cell).
    checkMemory(cubes * gridScale * sizeof(float) + elements * (8 * 4 + 8 * 16 + 64) +
                  static_cast<std::uint64_t>(locator.totalCells()) * sizeof(std::uint32_t),
      memoryLimit,
      "the gridlets, stitching elements and BVH");
  }
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
    std::int64_t numIndices[4] = { 0, 0, 0, 0 };
    std::vector<std::array<std::int64_t, 4>> itemStart(outputs.size());
    std::vector<std::int64_t> ghosts; // boundary-layer ghost ids; their vertices follow the cells'
    for (std::size_t i = 0; i < outputs.size(); ++i)
    {
      const ItemOutput& o = outputs[i];
      counts.dropped += o.dropped;
      for (int t = 0; t < 4; ++t)
      {
        itemStart[i][static_cast<std::size_t>(t)] = numIndices[t];
      }
      for (const ClassifiedElement& e : o.elements)
      {
        numIndices[e.type - PrimTet] += e.numCorners;
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
    for (int t = 0; t < 4; ++t)
    {
      mesh.elementIndices[t].resize(static_cast<std::size_t>(numIndices[t]));
    }
    parallelFor(outputs.size(),
      options.threads,
      [&](std::size_t i)
      {
        std::array<std::int64_t, 4> next = itemStart[i];
        for (const ClassifiedElement& e : outputs[i].elements)
        {
          const int t = e.type - PrimTet;
          std::uint32_t* out = mesh.elementIndices[t].data() + next[static_cast<std::size_t>(t)];
          for (int v = 0; v < e.numCorners; ++v)
          {
            out[v] = vertexIndex(e.corner[v]);
          }
          next[static_cast<std::size_t>(t)] += e.numCorners;
        }
      });
    counts.tets = mesh.numElements(0);
    counts.pyramids = mesh.numElements(1);
    counts.wedges = mesh.numElements(2);
    counts.hexes = mesh.numElements(3);
    counts.vertices = static_cast<std::int64_t>(mesh.vertices.size());
    for (std::int64_t n :
      { counts.gridlets, counts.tets, counts.pyramids, counts.wedges, counts.hexes })
    {
      if (n > static_cast<std::int64_t>(kPrimIndexMask))
      {
        throw std::invalid_argument("the dual mesh has more primitives of one type than the "
                                    "BVH can address (2^29)");
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
    auto addBox = [&](const glm::dvec3& a, const glm::dvec3& b, std::uint32_t ref)
    {
      lo.push_back(floatBelow(a));
      hi.push_back(floatAbove(b));
      refs.push_back(ref);
    };
    for (std::uint32_t g = 0; g < mesh.gridlets.size(); ++g)
    {
      const GridletHeader& h = mesh.gridlets[g];
      const double w = mesh.levelWidth[static_cast<std::size_t>(h.level)]; // as the sampler
      addBox((glm::dvec3(h.lower) + 0.5) * w,
        (glm::dvec3(h.lower + h.dims) + 0.5) * w,
        makePrimRef(PrimGridlet, g));
    }
    for (int t = 0; t < 4; ++t)
    {
      const int n = elementCorners(t);
      for (std::int64_t e = 0; e < mesh.numElements(t); ++e)
      {
        glm::ivec3 a = mesh.vertices[mesh.elementIndices[t][e * n]].pos2, b = a;
        for (int v = 1; v < n; ++v)
        {
          const glm::ivec3 p = mesh.vertices[mesh.elementIndices[t][e * n + v]].pos2;
          a = glm::min(a, p);
          b = glm::max(b, p);
        }
        addBox(0.5 * glm::dvec3(a),
          0.5 * glm::dvec3(b),
          makePrimRef(PrimTet + t, static_cast<std::uint32_t>(e)));
      }
    }
    mesh.bvh = buildBvh(lo, hi, refs, options.bvhLeafSize);
  }
  progress(1.0);
  return mesh;
}

} // namespace amrdm
