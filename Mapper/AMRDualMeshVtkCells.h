// The VTK cell of each stitching-element kind (mesh/ElementList.h): its cell type, the corners of
// the face whose winding decides the orientation, and the mirror permutation that turns an
// inverted element over (a symmetry of the reference cell, so the iso-parametric interpolant is
// unchanged). Used by vtkAMRDualMeshToUnstructuredGrid and the VTK oracle test. A kind added to
// ElementList.h without a row here fails to compile (static_assert), never drops out silently.
#ifndef AMRDualMeshVtkCells_h
#define AMRDualMeshVtkCells_h

#include "vtkCellType.h"
#include "vtkVersionMacros.h" // VTK_VERSION_NUMBER: the wedge's orientation changed in VTK 9.7

#include "mesh/ElementList.h"

namespace amrdm_vtk
{

/// VTK's wedge orientation (docs/VTK-COMPAT.md). Up to VTK 9.6 a wedge has positive volume when
/// its first triangle's right-hand normal points away from the second triangle; VTK 9.7 (topic
/// fix-wedge-point-ordering, on master from 9.6.20260310) turned the convention around so that
/// the point order matches the parametric coordinates, and the old order now has negative volume.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 20260310)
constexpr bool kWedgeNormalAwayFromRest = false;
#else
constexpr bool kWedgeNormalAwayFromRest = true;
#endif

struct VtkElementCell
{
  amrdm::ElementKind kind;
  unsigned char vtkType;
  /// Corners 0..faceCorners-1 wind the first face; VTK wants its right-hand normal to point
  /// toward the other corners (the apex, the opposite face), except for the wedge before VTK 9.7,
  /// whose first triangle's normal points away from the second (normalAwayFromRest).
  int faceCorners;
  bool normalAwayFromRest;
  int mirror[8];
};

constexpr VtkElementCell kVtkElementCells[] = {
  { amrdm::ElementKind::Tet, VTK_TETRA, 3, false, { 0, 2, 1, 3 } },
  { amrdm::ElementKind::Pyramid, VTK_PYRAMID, 4, false, { 0, 3, 2, 1, 4 } },
  { amrdm::ElementKind::Wedge, VTK_WEDGE, 3, kWedgeNormalAwayFromRest, { 0, 2, 1, 3, 5, 4 } },
  { amrdm::ElementKind::Hex, VTK_HEXAHEDRON, 4, false, { 0, 3, 2, 1, 4, 7, 6, 5 } },
};

static_assert(sizeof(kVtkElementCells) / sizeof(kVtkElementCells[0]) == amrdm::kElementKindCount,
  "every element kind of mesh/ElementList.h needs its VTK cell in AMRDualMeshVtkCells.h");

constexpr bool VtkElementCellsInKindOrder()
{
  for (int k = 0; k < amrdm::kElementKindCount; ++k)
  {
    if (int(kVtkElementCells[k].kind) != k)
    {
      return false;
    }
  }
  return true;
}
static_assert(VtkElementCellsInKindOrder(), "AMRDualMeshVtkCells.h rows follow ElementKind order");

} // namespace amrdm_vtk

#endif
