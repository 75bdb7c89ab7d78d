// Point sampling of the dual-mesh field: the first primitive (gridlet or stitching element) that
// claims a grid-space point gives its value. Host/device code.
#pragma once

#include "core/Tolerances.h"
#include "mesh/DualMesh.h"
#include "mesh/ElementTest.h"
#include "mesh/Elements.h"

namespace amrdm
{

/// Where a sample came from (debug views, tests).
struct SampleHit
{
  std::uint32_t prim = ~0u; ///< primitive reference (PrimType + index); ~0u = miss
  int cell = -1;            ///< dual cell inside a gridlet, -1 for elements
};

/// Gathers the corners of element `index` of kind `kind` (mesh/ElementList.h) into v as
/// (x, y, z, value) relative to its first corner (exact: doubled integer positions) and returns
/// that corner's doubled grid position in `anchor2`. `kind` must be in the list.
AMRDM_HD int gatherElement(const DualMeshView& mesh,
  int kind,
  std::uint32_t index,
  glm::vec4* v,
  glm::ivec3& anchor2)
{
  const int n = elementCorners(kind);
  const std::uint32_t* idx = mesh.elementIndices[kind] + std::size_t(index) * n;
  anchor2 = mesh.vertices[idx[0]].pos2;
  for (int i = 0; i < n; ++i)
  {
    const ElementVertex& e = mesh.vertices[idx[i]];
    v[i] = glm::vec4(0.5f * glm::vec3(e.pos2 - anchor2), e.value);
  }
  return n;
}

/// Element kind `kind`'s test of q (its frame, corners v): the list's sample function, one case
/// per row of mesh/ElementList.h. A kind outside the list claims nothing: there is no fallback
/// shape (DualMesh::validate() keeps such kinds out of every mesh a renderer sees).
AMRDM_HD bool sampleElementOfKind(int kind,
  const glm::vec4* v,
  const glm::vec3& q,
  const ElementTestParams& params,
  float& value)
{
  switch (kind)
  {
#define AMRDM_ELEMENT_SAMPLE(k, name, member, corners, sample, ...)                                \
  case int(ElementKind::k):                                                                        \
    return sample(v, q, params, value);
    AMRDM_ELEMENTS(AMRDM_ELEMENT_SAMPLE)
#undef AMRDM_ELEMENT_SAMPLE
    default:
      return false;
  }
}

/// Tests one primitive at grid-space point p (glm::vec3, or glm::dvec3 for host queries that
/// need more than float's 24 bits, e.g. deep hierarchies). True if it claims p; then `value`
/// holds the interpolant. Every test runs in the primitive's own frame (gridlet lower corner,
/// element first corner), so float only carries positions relative to the primitive. A
/// reference whose type is neither a gridlet nor a kind of mesh/ElementList.h claims nothing.
template<typename T>
AMRDM_HD bool samplePrimitive(const DualMeshView& mesh,
  std::uint32_t ref,
  const glm::vec<3, T>& p,
  const ElementTestParams& params,
  float& value,
  int* cell = nullptr)
{
  const std::uint32_t type = primType(ref);
  const std::uint32_t index = primIndex(ref);
  if (type == PrimGridlet)
  {
    const GridletHeader& g = mesh.gridlets[index];
    return sampleGridlet(
      g, mesh.gridletScalars, mesh.levelWidth[g.level], mesh.gridletOrigin, p, value, cell);
  }
  if (!isElementPrimType(type))
  {
    return false;
  }
  const int kind = primElementKind(type);
  glm::vec4 v[kMaxElementCorners];
  glm::ivec3 anchor2;
  const int n = gatherElement(mesh, kind, index, v, anchor2);
  const glm::vec3 q(p - T(0.5) * glm::vec<3, T>(anchor2)); // p in the element's frame
  glm::vec3 lo(v[0]), hi(v[0]);
  for (int i = 1; i < n; ++i)
  {
    lo = glm::min(lo, glm::vec3(v[i]));
    hi = glm::max(hi, glm::vec3(v[i]));
  }
  // Leaves hold several primitives: reject by the element's own box before any Newton work.
  // The box is padded by kElementBoxPad (core/Tolerances.h) so that faces stay watertight.
  const glm::vec3 pad = (hi - lo) * kElementBoxPad;
  if (glm::any(glm::lessThan(q, lo - pad)) || glm::any(glm::greaterThan(q, hi + pad)))
  {
    return false;
  }
  if (cell)
  {
    *cell = -1;
  }
  return sampleElementOfKind(kind, v, q, params, value);
}

/// The field at grid-space point p (glm::vec3 or glm::dvec3, see samplePrimitive). False where
/// no primitive claims p (outside the dual mesh, in a hole, or in a region the build left out).
template<typename T>
AMRDM_HD bool sampleField(const DualMeshView& mesh,
  const glm::vec<3, T>& p,
  const ElementTestParams& params,
  float& value,
  SampleHit* hit = nullptr)
{
  float result = 0.0f;
  int cell = -1;
  std::uint32_t found = ~0u;
  bvhPointQuery(mesh.bvh,
    p,
    [&](std::uint32_t ref)
    {
      if (samplePrimitive(mesh, ref, p, params, result, &cell))
      {
        found = ref;
        return true;
      }
      return false;
    });
  if (hit)
  {
    hit->prim = found;
    hit->cell = cell;
  }
  if (found == ~0u)
  {
    return false;
  }
  value = result;
  return true;
}

/// Test-only: every primitive that claims p, up to maxHits. Returns the number of hits.
template<typename T>
AMRDM_HD int sampleFieldAllHits(const DualMeshView& mesh,
  const glm::vec<3, T>& p,
  const ElementTestParams& params,
  float* values,
  std::uint32_t* refs,
  int maxHits)
{
  int hits = 0;
  bvhPointQuery(mesh.bvh,
    p,
    [&](std::uint32_t ref)
    {
      float v;
      if (samplePrimitive(mesh, ref, p, params, v) && hits < maxHits)
      {
        values[hits] = v;
        refs[hits] = ref;
        ++hits;
      }
      return false;
    });
  return hits;
}

} // namespace amrdm
