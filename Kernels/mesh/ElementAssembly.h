// Steps 3 and 4 of the dual-mesh build (DualMeshBuilder.cpp), on all threads: the classified
// stitching elements of every work item become the mesh's shared vertices and per-kind index
// arrays, and every primitive (gridlet or element) gets its conservative float box for the BVH,
// which buildPrimitiveBvh builds (the vertex-centred builder's last step too).
// No step is a serial pass over the AMR cells or the elements. Host code.
#pragma once

#include "accel/BvhBuilder.h"
#include "mesh/DualCellDiscovery.h"
#include "mesh/DualMesh.h"

#include <vector>

namespace amrdm
{
class BoundaryLayer;

namespace detail
{

/// Fills mesh.vertices (the distinct corner cells in global-id order, then the boundary-layer
/// ghosts in id order), mesh.elementIndices (per kind, work items in order) and the element,
/// vertex and dropped counts, and frees every item's element records. The result does not
/// depend on `threads`. Throws std::invalid_argument, naming the element, when a record is not
/// a kind of mesh/ElementList.h with its number of corners, and when the vertices or the
/// elements of one kind exceed what a primitive reference can address (2^29).
void assembleElements(const BoundaryLayer& boundary,
  std::vector<ItemOutput>& outputs,
  int threads,
  DualMesh& mesh);

/// The BVH input: one box per gridlet (cut at the domain faces, as the sampler) and per element
/// (its corners' bounds), exact in double and rounded outwards to float, with its primitive
/// reference; gridlets first, then the element kinds in list order.
DefaultInitVector<BvhPrimBox> primitiveBoxes(const DualMesh& mesh, int threads);

/// Step 4 of both builders (DualMeshBuilder.cpp, VertexMeshBuilder.cpp): mesh.bvh over
/// primitiveBoxes() with `leafSize` primitives per leaf, then mesh.validate().
void buildPrimitiveBvh(DualMesh& mesh, int leafSize, int threads);

} // namespace detail
} // namespace amrdm
