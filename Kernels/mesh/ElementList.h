// The stitching-element kinds, one row each: the single place an element kind is registered.
// The enum ElementKind and the primitive types of BVH references (accel/Bvh.h PrimType), the
// per-kind index arrays of the dual mesh (DualMesh, DualMeshView, the CUDA uploads and their
// memory-ledger names), the builder's per-kind counts and BVH boxes, the sampler's dispatch
// (sampling/FieldSampler.h: exhaustive, an unknown type claims nothing), the majorant and
// culling passes, the debug colours (transport/DebugViews.h) and the JSON counts all come from
// this list. Rows are in PrimType order after the gridlet (PrimGridlet = 0, then one per row):
// the values are stored in BVH primitive references, append, never reorder. A reference has
// 3 type bits, so at most 7 kinds fit. Host/device code. How to add a kind: docs/ARCHITECTURE.md.
//
// X(Kind, name, counts member, corners, sample function, debug colour r, g, b)
//   name:           lower-case, singular (messages, ledger names)
//   counts member:  the DualMeshCounts field that counts this kind (JSON key, vtkAMRDualMesh)
//   corners:        vertices per element, VTK corner order, at most kMaxElementCorners (8)
//   sample function (mesh/Elements.h): AMRDM_HD bool f(const glm::vec4* v, const glm::vec3& p,
//     const ElementTestParams&, float& value): v are the corners (x, y, z, value) relative to
//     the first corner, p in that frame; true if the element claims p, then value = interpolant.
#pragma once

#include "core/HostDevice.h"

#include <string>

#define AMRDM_ELEMENTS(X)                                                                          \
  /* linear, closed-form barycentric coordinates */                                                \
  X(Tet, "tet", tets, 4, sampleTet, 0.9f, 0.1f, 0.1f)                                              \
  /* corners 0-3 base (may be twisted), 4 apex */                                                  \
  X(Pyramid, "pyramid", pyramids, 5, samplePyramid, 0.1f, 0.8f, 0.1f)                              \
  /* triangle 0,1,2 and triangle 3,4,5 (3 above 0) */                                              \
  X(Wedge, "wedge", wedges, 6, sampleWedge, 0.2f, 0.4f, 1.0f)                                      \
  /* trilinear (bilinear faces), corners 0-3 bottom, 4-7 top; repeated corners allowed */          \
  X(Hex, "hex", hexes, 8, sampleHex, 1.0f, 0.55f, 0.0f)

namespace amrdm
{

/// A stitching-element kind; also the index of its array in DualMesh::elementIndices.
enum class ElementKind : int
{
#define AMRDM_ELEMENT_ENUM(kind, ...) kind,
  AMRDM_ELEMENTS(AMRDM_ELEMENT_ENUM)
#undef AMRDM_ELEMENT_ENUM
};

/// One element kind's static description.
struct ElementKindInfo
{
  ElementKind kind;
  const char* name; ///< "tet", ...
  int corners;      ///< vertices per element
};

constexpr ElementKindInfo kElementKinds[] = {
#define AMRDM_ELEMENT_INFO(kind, name, member, corners, ...) { ElementKind::kind, name, corners },
  AMRDM_ELEMENTS(AMRDM_ELEMENT_INFO)
#undef AMRDM_ELEMENT_INFO
};

/// Number of element kinds: every per-kind array and loop is sized by it.
constexpr int kElementKindCount = int(sizeof(kElementKinds) / sizeof(kElementKinds[0]));

/// True for 0 <= kind < kElementKindCount.
AMRDM_HD constexpr bool isElementKind(int kind)
{
  return kind >= 0 && kind < kElementKindCount;
}

/// Corners of element kind `kind`; 0 for a kind not in the list (validated where data enters).
AMRDM_HD constexpr int elementCorners(int kind)
{
  switch (kind)
  {
#define AMRDM_ELEMENT_CORNERS(k, name, member, corners, ...)                                       \
  case int(ElementKind::k):                                                                        \
    return corners;
    AMRDM_ELEMENTS(AMRDM_ELEMENT_CORNERS)
#undef AMRDM_ELEMENT_CORNERS
    default:
      return 0;
  }
}

/// Most corners of any kind (fixed-size corner buffers).
constexpr int kMaxElementCorners = []()
{
  int m = 0;
  for (const ElementKindInfo& k : kElementKinds)
  {
    m = k.corners > m ? k.corners : m;
  }
  return m;
}();
static_assert(kMaxElementCorners <= 8, "a dual cell has 8 corners: no element kind has more");

/// Name of element kind `kind` ("tet", ...), "unknown" for a kind not in the list.
inline const char* elementKindName(int kind)
{
  return isElementKind(kind) ? kElementKinds[kind].name : "unknown";
}

/// The list's names, "tet, pyramid, wedge, hex" (messages).
inline std::string elementKindNames()
{
  std::string names;
  for (const ElementKindInfo& k : kElementKinds)
  {
    names += (names.empty() ? "" : ", ") + std::string(k.name);
  }
  return names;
}

} // namespace amrdm
