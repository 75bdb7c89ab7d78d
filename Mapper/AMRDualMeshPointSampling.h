// Sampling a built dual mesh at world points, for vtkAMRDualMesh::Sample / SamplePoints (and
// through them the probe filter): the field's exact interpolant, NaN or a cleared mask bit
// where no primitive covers the point. Private to the Mapper module; not wrapped.
#ifndef AMRDualMeshPointSampling_h
#define AMRDualMeshPointSampling_h

#include "vtkType.h"

#include "mesh/ElementTest.h"

class vtkDataArray;
class vtkUnsignedCharArray;

namespace amrdm
{
struct DualMesh;
}

namespace amrdm_vtk
{
/// The kernels' element test for a value of the Mapper module's ElementTest settings
/// (vtkAMRDualMeshVolumeMapper::ElementTests, clamped to them by the setters): the one
/// conversion, used by vtkAMRDualMesh's sampling and by the volume mapper's frame.
amrdm::ElementTest ToElementTest(int elementTest);

/// The element test vtkAMRDualMesh's ElementTest and MaxNewtonIterations ask for.
amrdm::ElementTestParams MakeElementTestParams(int elementTest, int maxNewtonIterations);

/// The field at world point `x`, NaN outside the mesh.
double SampleAt(const amrdm::DualMesh& mesh,
  const amrdm::ElementTestParams& params,
  const double x[3]);

/// Samples every tuple of `points` (3 components, world coordinates) on `threads` threads:
/// `values` (1 component) gets the field or 0, `mask` 1 where a primitive covers the point, else
/// 0. Returns the number of points covered.
vtkIdType SamplePointArray(const amrdm::DualMesh& mesh,
  const amrdm::ElementTestParams& params,
  int threads,
  vtkDataArray* points,
  vtkDataArray* values,
  vtkUnsignedCharArray* mask);
}

#endif
