// Steps 3 and 4 of the dual-mesh build on all threads (see ElementAssembly.h). Vertices are found
// through a rank bitmap over the AMR cells (one bit per cell and a 4-byte rank per 64 cells,
// 0.19 B per cell instead of a 4-byte map entry; freed on return): items set the bits of their
// corner cells, chunks of words count and then rank the bits in id order (a vertex's index is its
// word's rank plus the set bits below it in the word), and the index arrays are written per item
// at offsets from a prefix sum over items. Every pass splits its work by item, by chunk of ids or
// by chunk of primitives.
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
/// Ids per chunk of the ghost pass; words (64 ids each) per chunk of the bitmap passes.
constexpr std::size_t kIdsPerChunk = std::size_t(1) << 20;
constexpr std::size_t kWordsPerChunk = std::size_t(1) << 14;

/// Which AMR cells are stitching vertices, and each one's vertex index (its rank in id order).
class VertexRank
{
public:
  explicit VertexRank(std::size_t numIds)
    : NumWords((numIds + 63) / 64)
    , Bits(new std::uint64_t[NumWords])
    , Rank(new std::uint32_t[NumWords])
  {
  }
  std::size_t numWords() const { return this->NumWords; }
  std::uint64_t* bits() { return this->Bits.get(); }
  std::uint32_t* ranks() { return this->Rank.get(); }
  /// Marks cell id (atomic: items share corners).
  void mark(std::size_t id)
  {
    __atomic_fetch_or(&this->Bits[id / 64], std::uint64_t(1) << (id % 64), __ATOMIC_RELAXED);
  }
  /// The vertex index of a marked cell id (after the ranks are written).
  std::uint32_t vertexOf(std::size_t id) const
  {
    const std::uint64_t below = this->Bits[id / 64] & ((std::uint64_t(1) << (id % 64)) - 1);
    return this->Rank[id / 64] + static_cast<std::uint32_t>(__builtin_popcountll(below));
  }

private:
  std::size_t NumWords;
  std::unique_ptr<std::uint64_t[]> Bits;
  std::unique_ptr<std::uint32_t[]> Rank;
};
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
  VertexRank rank(numIds);
  const std::size_t numWords = rank.numWords();
  const std::size_t numChunks = chunkCount(numWords, kWordsPerChunk);
  parallelFor(numChunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numWords, (c + 1) * kWordsPerChunk);
      std::fill(rank.bits() + c * kWordsPerChunk, rank.bits() + end, std::uint64_t(0));
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
            rank.mark(static_cast<std::size_t>(e.corner[v]));
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

  // Rank the marked cells in id order: count per chunk of words, prefix, then rank per chunk.
  std::vector<std::size_t> chunkStart(numChunks + 1, 0);
  parallelFor(numChunks,
    threads,
    [&](std::size_t c)
    {
      const std::size_t end = std::min(numWords, (c + 1) * kWordsPerChunk);
      std::size_t n = 0;
      for (std::size_t w = c * kWordsPerChunk; w < end; ++w)
      {
        n += static_cast<std::size_t>(__builtin_popcountll(rank.bits()[w]));
      }
      chunkStart[c + 1] = n;
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
      const std::size_t end = std::min(numWords, (c + 1) * kWordsPerChunk);
      std::size_t next = chunkStart[c];
      for (std::size_t w = c * kWordsPerChunk; w < end; ++w)
      {
        rank.ranks()[w] = static_cast<std::uint32_t>(next);
        for (std::uint64_t b = rank.bits()[w]; b != 0; b &= b - 1)
        {
          const auto id = static_cast<std::int64_t>(w * 64 + std::size_t(__builtin_ctzll(b)));
          // Twice a cell centre is an integer (within +-2^31 after validate()): exact.
          const glm::dvec3 p2 = 2.0 * boundary.centre(id);
          mesh.vertices[next++] = ElementVertex{ glm::ivec3(glm::round(p2)), boundary.value(id) };
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
                     : rank.vertexOf(static_cast<std::size_t>(id));
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

DefaultInitVector<BvhPrimBox> primitiveBoxes(const DualMesh& mesh, int threads)
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
  DefaultInitVector<BvhPrimBox> prims(numPrims);
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
          prims[p].ref = makePrimRef(PrimGridlet, static_cast<std::uint32_t>(p));
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
          prims[p].ref = makePrimRef(elementPrimType(k), static_cast<std::uint32_t>(e));
        }
        prims[p].lo = floatBelow(a);
        prims[p].hi = floatAbove(b);
      }
    });
  return prims;
}

void buildPrimitiveBvh(DualMesh& mesh, int leafSize, int threads)
{
  mesh.bvh = buildBvh(primitiveBoxes(mesh, threads), leafSize, threads);
  mesh.validate();
}

} // namespace detail
} // namespace amrdm
