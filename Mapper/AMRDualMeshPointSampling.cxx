#include "AMRDualMeshPointSampling.h"

#include "vtkDataArray.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkUnsignedCharArray.h"

#include "core/ParallelFor.h"
#include "mesh/DualMesh.h"
#include "sampling/FieldSampler.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace
{
/// Grid-space point in double: deep hierarchies have grid coordinates beyond float's 2^24, and
/// the sampler forms every primitive-local coordinate in double before it becomes float.
glm::dvec3 toGrid(const amrdm::DualMesh& mesh, const double x[3])
{
  return mesh.gridFromWorld(glm::dvec3(x[0], x[1], x[2]));
}
}

namespace amrdm_vtk
{
amrdm::ElementTest ToElementTest(int elementTest)
{
  return elementTest == vtkAMRDualMeshVolumeMapper::ELEMENT_TEST_PLANAR_FACES
           ? amrdm::ElementTest::PlanarFaces
           : amrdm::ElementTest::Bilinear;
}

amrdm::ElementTestParams MakeElementTestParams(int elementTest, int maxNewtonIterations)
{
  amrdm::ElementTestParams params;
  params.test = ToElementTest(elementTest);
  params.maxNewtonIterations = maxNewtonIterations;
  return params;
}

double SampleAt(const amrdm::DualMesh& mesh,
  const amrdm::ElementTestParams& params,
  const double x[3])
{
  float value;
  if (amrdm::sampleField(mesh.view(), toGrid(mesh, x), params, value))
  {
    return value;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

vtkIdType SamplePointArray(const amrdm::DualMesh& mesh,
  const amrdm::ElementTestParams& params,
  int threads,
  vtkDataArray* points,
  vtkDataArray* values,
  vtkUnsignedCharArray* mask)
{
  const vtkIdType n = points->GetNumberOfTuples();
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  mask->SetNumberOfComponents(1);
  mask->SetNumberOfTuples(n);
  const amrdm::DualMeshView view = mesh.view();
  constexpr vtkIdType chunk = 4096;
  std::vector<vtkIdType> found(static_cast<std::size_t>((n + chunk - 1) / chunk), 0);
  amrdm::parallelFor(found.size(),
    threads,
    [&](std::size_t c)
    {
      const vtkIdType end = std::min(n, static_cast<vtkIdType>(c + 1) * chunk);
      for (vtkIdType i = static_cast<vtkIdType>(c) * chunk; i < end; ++i)
      {
        double x[3];
        points->GetTuple(i, x);
        float v = 0.0f;
        const bool hit = amrdm::sampleField(view, toGrid(mesh, x), params, v);
        values->SetComponent(i, 0, hit ? v : 0.0);
        mask->SetValue(i, hit ? 1 : 0);
        found[c] += hit ? 1 : 0;
      }
    });
  vtkIdType total = 0;
  for (vtkIdType f : found)
  {
    total += f;
  }
  return total;
}
}
