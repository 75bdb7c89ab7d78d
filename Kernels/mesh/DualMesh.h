// The dual mesh in memory: gridlets, stitching elements and the BVH over both. Host-owned
// (std::vector); DualMeshView is the plain-pointer view that kernels on the CPU or GPU read.
#pragma once

#include "accel/Bvh.h"
#include "core/DefaultInitAllocator.h"
#include "mesh/Gridlet.h"

#include <cstdint>
#include <string>
#include <vector>

namespace amrdm
{

/// Bytes by category, as reported to users (C++, Python, amrdm-render --stats).
struct MemoryReport
{
  std::uint64_t gridletScalars = 0;  ///< (dims+1)^3 floats per gridlet, NaN slots included
  std::uint64_t gridletHeaders = 0;  ///< 32 B per gridlet
  std::uint64_t elementVertices = 0; ///< 16 B per stitching vertex (ElementVertex)
  std::uint64_t elementIndices = 0;  ///< 4 B per element corner
  std::uint64_t bvh = 0;             ///< nodes plus primitive references
  std::int64_t leafCells = 0;        ///< visible AMR leaf cells the mesh was built from

  std::uint64_t total() const
  {
    return gridletScalars + gridletHeaders + elementVertices + elementIndices + bvh;
  }
  double bytesPerLeafCell() const
  {
    return leafCells > 0 ? double(total()) / double(leafCells) : 0.0;
  }
  std::string toJson() const;
};

/// Counts of what the builder produced.
struct DualMeshCounts
{
  std::int64_t leafCells = 0;
  std::int64_t perfectCubes = 0; ///< dual cells stored in gridlets
  std::int64_t gridlets = 0;
  /// One count per element kind (tets, pyramids, wedges, hexes: mesh/ElementList.h).
#define AMRDM_ELEMENT_COUNT(kind, name, member, ...) std::int64_t member = 0;
  AMRDM_ELEMENTS(AMRDM_ELEMENT_COUNT)
#undef AMRDM_ELEMENT_COUNT
  std::int64_t degenerateHexes = 0; ///< hexes with repeated corners (subset of hexes)
  std::int64_t dropped = 0;         ///< zero-volume dual cells
  std::int64_t vertices = 0;        ///< stitching-element vertices
  std::int64_t nonFiniteValues = 0; ///< leaf values that were NaN/Inf and became holes
  /// The count of element kind `kind` (0 <= kind < kElementKindCount).
  std::int64_t& elements(int kind);
  std::int64_t elements(int kind) const;
  std::int64_t totalElements() const;
  std::string toJson() const;
};

/// A stitching-element corner: a leaf-cell centre and its value, 16 bytes. Cell centres lie on
/// half-integers of the finest grid, so the position is stored exactly as twice its grid
/// coordinates (int32: grid coordinates stay within +-2^30). Kernels work relative to an element's
/// first corner, so positions deep inside a 2^25-cell grid keep full float precision.
struct ElementVertex
{
  glm::ivec3 pos2; ///< 2 * grid position
  float value;
};
static_assert(sizeof(ElementVertex) == 16, "ElementVertex must stay 16 bytes");

/// What kernels read. Every pointer may be null when its count is 0.
struct DualMeshView
{
  const float* levelWidth = nullptr; ///< cell width of each level in finest units
  int numLevels = 0;
  float gridletOrigin = 0.5f; ///< DualMesh::gridletOrigin
  const GridletHeader* gridlets = nullptr;
  const float* gridletScalars = nullptr;
  const ElementVertex* vertices = nullptr;
  const std::uint32_t* elementIndices[kElementKindCount] = {}; ///< per kind (ElementList.h)
  BvhView bvh;
};

struct DualMesh
{
  std::vector<float> levelWidth;
  /// Where a gridlet's vertex lattice sits: vertex i of a level-L gridlet is at grid position
  /// (lower + i + gridletOrigin) * levelWidth[L]. 0.5 for the dual mesh (the vertices are cell
  /// centres); 0 for vertex-centred data (mesh/VertexMeshBuilder.h: the vertices are the cells'
  /// corners, the primal mesh).
  float gridletOrigin = 0.5f;
  std::vector<GridletHeader> gridlets;
  /// The large arrays are left uninitialised on resize and sit in huge pages when large
  /// (core/DefaultInitAllocator.h): the builder writes every element once, in parallel.
  DefaultInitVector<float> gridletScalars;
  DefaultInitVector<ElementVertex> vertices;
  /// Indices into `vertices`, one array per element kind (mesh/ElementList.h), VTK corner order.
  DefaultInitVector<std::uint32_t> elementIndices[kElementKindCount];
  Bvh bvh;
  /// world = sceneOrigin + origin + finestSpacing * grid (see AmrHierarchy.h). Renderers, cameras,
  /// lights and majorant grids use the scene frame, world - sceneOrigin: convert world points
  /// with sceneFromWorld() / gridFromWorld(), in double, before they become float.
  glm::dvec3 sceneOrigin{ 0.0 };
  glm::dvec3 origin{ 0.0 };
  glm::dvec3 finestSpacing{ 1.0 };
  /// Grid-space box whose faces carry the clamped boundary layer (AmrHierarchy::domainBox()):
  /// stitching vertices on its faces are ghosts, half a cell from the cells they copy.
  glm::ivec3 domainLower{ 0 };
  glm::ivec3 domainUpper{ 0 };
  DualMeshCounts counts;

  std::int64_t numElements(int kind) const
  {
    return static_cast<std::int64_t>(this->elementIndices[kind].size()) / elementCorners(kind);
  }
  glm::dvec3 sceneFromWorld(const glm::dvec3& world) const { return world - this->sceneOrigin; }
  glm::dvec3 gridFromWorld(const glm::dvec3& world) const
  {
    return (this->sceneFromWorld(world) - this->origin) / this->finestSpacing;
  }
  glm::dvec3 worldFromGrid(const glm::dvec3& grid) const
  {
    return this->sceneOrigin + (this->origin + this->finestSpacing * grid);
  }
  DualMeshView view() const;
  MemoryReport memoryReport() const;
  /// Throws std::invalid_argument, naming what was wrong and what was expected, unless every
  /// element index array holds whole elements of its kind with indices into `vertices`, and every
  /// BVH primitive reference has a known type (a gridlet or a kind of mesh/ElementList.h) and an
  /// index in range. buildDualMesh() and the CUDA uploads call it: a type outside the list never
  /// reaches a sampler.
  void validate() const;
  /// Grid-space bounds of everything that can be sampled.
  void gridBounds(glm::vec3& lo, glm::vec3& hi) const;
};

} // namespace amrdm
