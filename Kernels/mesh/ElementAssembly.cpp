// Steps 3 and 4 of the dual-mesh build on all threads (see ElementAssembly.h). Vertices are found
// through a dense id -> vertex map (4 B per AMR cell, allocated uninitialised and first touched
// in parallel, freed on return): items mark their corner cells, chunks of the map count and then
// number the marks in id order, and the index arrays are written per item at offsets from a prefix
// sum over items. Every pass splits its work by item, by chunk of ids or by chunk of primitives.
#include "mesh/ElementAssembly.h"

#include "core/ParallelFor.h"
#include "mesh/BoundaryLayer.h"
#include "mesh/GridletBuilder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace amrdm
{
namespace detail
{

namespace
{
constexpr std::uint32_t kUnused = ~std::uint32_t(0);
/// Ids per chunk of the passes over the dense id -> vertex map.
constexpr std::size_t kIdsPerChunk = std::size_t(1) << 20;
/// Primitives per chunk of the box pass.
constexpr std::size_t kPrimsPerChunk = std::size_t(1) << 16;

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

/// What one work item's elements add: corners per kind, degenerate hexes, ghost corners.
struct ItemTally
{
  std::array<std::int64_t, kElementKindCount> indices{};
  std::int64_t degenerateHexes = 0;
  std::vector<std::int64_t> ghosts;
};

void checkAddressable(std::size_t n, const std::string& what)
{
  if (n > kPrimIndexMask)
  {
    throw std::invalid_argument("the dual mesh needs " + std::to_string(n) + " " + what +
                                "; a primitive reference addresses at most 2^29");
  }
}

/// Chunks of `size` that cover n items.
std::size_t chunkCount(std::size_t n, std::size_t size)
{
  return (n + size - 1) / size;
}
} // namespace

void assembleElements(const BoundaryLayer& boundary,
  std::vector<ItemOutput>& outputs,
  int threads,
  DualMesh& mesh)
{
  DualMeshCounts& counts = mesh.counts;
  const std::size_t numIds = static_cast<std::size_t>(boundary.locator().totalCells());
  const std::size_t numChunks = chunkCount(numIds, kIdsPerChunk);
  std::unique_ptr<std::uint32_t[]> vertexOf(new std::uint32_t[numIds]);
  parallelFor(numChunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numIds, (c + 1) * kIdsPerChunk);
      std::fill(vertexOf.get() + c * kIdsPerChunk, vertexOf.get() + end, kUnused);
    });

  // Mark the corner cells (relaxed atomic stores of one value: items share corners), tally.
  std::vector<ItemTally> tally(outputs.size());
  parallelFor(outputs.size(),
    threads,
    [&](std::size_t i)
    {
      ItemTally& t = tally[i];
      for (const ClassifiedElement& e : outputs[i].elements)
      {
        const int kind = primElementKind(std::uint32_t(e.type));
        if (!isElementPrimType(std::uint32_t(e.type)) || e.numCorners != elementCorners(kind))
        {
          throw std::invalid_argument(
            "a dual cell was classified as primitive type " + std::to_string(e.type) + " with " +
            std::to_string(e.numCorners) + " corners; expected a stitching-element kind of " +
            "mesh/ElementList.h (" + elementKindNames() + ") with its number of corners");
        }
        t.indices[static_cast<std::size_t>(kind)] += e.numCorners;
        t.degenerateHexes += e.degenerateHex ? 1 : 0;
        for (int v = 0; v < e.numCorners; ++v)
        {
          if (boundary.isGhost(e.corner[v]))
          {
            t.ghosts.push_back(e.corner[v]);
          }
          else
          {
            __atomic_store_n(
              &vertexOf[static_cast<std::size_t>(e.corner[v])], 0u, __ATOMIC_RELAXED);
          }
        }
      }
    });

  // Per-item offsets into each kind's index array (a prefix sum over items, not elements).
  std::vector<std::array<std::int64_t, kElementKindCount>> itemStart(outputs.size());
  std::array<std::int64_t, kElementKindCount> numIndices{};
  std::vector<std::int64_t> ghosts;
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    itemStart[i] = numIndices;
    for (std::size_t k = 0; k < numIndices.size(); ++k)
    {
      numIndices[k] += tally[i].indices[k];
    }
    counts.dropped += outputs[i].dropped;
    counts.degenerateHexes += tally[i].degenerateHexes;
    ghosts.insert(ghosts.end(), tally[i].ghosts.begin(), tally[i].ghosts.end());
    std::vector<std::int64_t>().swap(tally[i].ghosts);
  }
  std::sort(ghosts.begin(), ghosts.end());
  ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());

  // Number the marked cells in id order: count per chunk, prefix, then number per chunk.
  std::vector<std::size_t> chunkStart(numChunks + 1, 0);
  parallelFor(numChunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numIds, (c + 1) * kIdsPerChunk);
      chunkStart[c + 1] = static_cast<std::size_t>(
        std::count(vertexOf.get() + c * kIdsPerChunk, vertexOf.get() + end, 0u));
    });
  for (std::size_t c = 0; c < numChunks; ++c)
  {
    chunkStart[c + 1] += chunkStart[c];
  }
  const std::size_t firstGhost = chunkStart[numChunks];
  checkAddressable(firstGhost + ghosts.size(), "stitching vertices");
  mesh.vertices.resize(firstGhost + ghosts.size());
  parallelFor(numChunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numIds, (c + 1) * kIdsPerChunk);
      std::size_t next = chunkStart[c];
      for (std::size_t id = c * kIdsPerChunk; id < end; ++id)
      {
        if (vertexOf[id] != kUnused)
        {
          vertexOf[id] = static_cast<std::uint32_t>(next);
          // Twice a cell centre is an integer (within +-2^31 after validate()): exact.
          const glm::dvec3 p2 = 2.0 * boundary.centre(static_cast<std::int64_t>(id));
          mesh.vertices[next++] = ElementVertex{ glm::ivec3(glm::round(p2)),
            boundary.value(static_cast<std::int64_t>(id)) };
        }
      }
    });
  parallelFor(chunkCount(ghosts.size(), kIdsPerChunk),
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(ghosts.size(), (c + 1) * kIdsPerChunk);
      for (std::size_t g = c * kIdsPerChunk; g < end; ++g)
      {
        // A ghost's centre lies on the domain faces: twice it is an integer too.
        const glm::dvec3 p2 = 2.0 * boundary.centre(ghosts[g]);
        mesh.vertices[firstGhost + g] =
          ElementVertex{ glm::ivec3(glm::round(p2)), boundary.value(ghosts[g]) };
      }
    });

  // Index arrays, per item at its offsets.
  for (int k = 0; k < kElementKindCount; ++k)
  {
    checkAddressable(static_cast<std::size_t>(numIndices[static_cast<std::size_t>(k)]) /
                       static_cast<std::size_t>(elementCorners(k)),
      std::string(elementKindName(k)) + "s");
    mesh.elementIndices[k].resize(
      static_cast<std::size_t>(numIndices[static_cast<std::size_t>(k)]));
  }
  parallelFor(outputs.size(),
    threads,
    [&](std::size_t i)
    {
      std::array<std::int64_t, kElementKindCount> next = itemStart[i];
      for (const ClassifiedElement& e : outputs[i].elements)
      {
        const auto k = static_cast<std::size_t>(primElementKind(std::uint32_t(e.type)));
        std::uint32_t* out = mesh.elementIndices[k].data() + next[k];
        for (int v = 0; v < e.numCorners; ++v)
        {
          const std::int64_t id = e.corner[v];
          out[v] = boundary.isGhost(id)
                     ? static_cast<std::uint32_t>(
                         firstGhost +
                         static_cast<std::size_t>(
                           std::lower_bound(ghosts.begin(), ghosts.end(), id) - ghosts.begin()))
                     : vertexOf[static_cast<std::size_t>(id)];
        }
        next[k] += e.numCorners;
      }
      std::vector<ClassifiedElement>().swap(outputs[i].elements);
    });
  counts.vertices = static_cast<std::int64_t>(mesh.vertices.size());
  for (int k = 0; k < kElementKindCount; ++k)
  {
    counts.elements(k) = mesh.numElements(k);
  }
}

void primitiveBoxes(const DualMesh& mesh,
  int threads,
  std::vector<glm::vec3>& lo,
  std::vector<glm::vec3>& hi,
  std::vector<std::uint32_t>& refs)
{
  // Primitive ranges: gridlets, then each kind; refs in that order.
  std::array<std::size_t, kElementKindCount + 2> first{};
  first[1] = mesh.gridlets.size();
  for (int k = 0; k < kElementKindCount; ++k)
  {
    first[static_cast<std::size_t>(k) + 2] =
      first[static_cast<std::size_t>(k) + 1] + static_cast<std::size_t>(mesh.numElements(k));
  }
  const std::size_t numPrims = first.back();
  lo.resize(numPrims);
  hi.resize(numPrims);
  refs.resize(numPrims);
  parallelFor(chunkCount(numPrims, kPrimsPerChunk),
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numPrims, (c + 1) * kPrimsPerChunk);
      for (std::size_t p = c * kPrimsPerChunk; p < end; ++p)
      {
        // Boxes are exact in double and rounded outwards to float, so that they contain every
        // point their primitive claims even where grid coordinates exceed float's 2^24.
        glm::dvec3 a, b;
        if (p < first[1])
        {
          gridletGridBox(mesh, mesh.gridlets[p], a, b); // as the sampler: cut at domain faces
          refs[p] = makePrimRef(PrimGridlet, static_cast<std::uint32_t>(p));
        }
        else
        {
          const int k =
            static_cast<int>(std::upper_bound(first.begin(), first.end(), p) - first.begin()) - 2;
          const std::size_t e = p - first[static_cast<std::size_t>(k) + 1];
          const int n = elementCorners(k);
          const std::uint32_t* idx = mesh.elementIndices[k].data() + e * std::size_t(n);
          glm::ivec3 a2 = mesh.vertices[idx[0]].pos2, b2 = a2;
          for (int v = 1; v < n; ++v)
          {
            a2 = glm::min(a2, mesh.vertices[idx[v]].pos2);
            b2 = glm::max(b2, mesh.vertices[idx[v]].pos2);
          }
          a = 0.5 * glm::dvec3(a2);
          b = 0.5 * glm::dvec3(b2);
          refs[p] = makePrimRef(elementPrimType(k), static_cast<std::uint32_t>(e));
        }
        lo[p] = floatBelow(a);
        hi[p] = floatAbove(b);
      }
    });
}

} // namespace detail
} // namespace amrdm
