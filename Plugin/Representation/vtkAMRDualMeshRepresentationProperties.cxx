// vtkAMRDualMeshRepresentation: the properties forwarded unchanged to the vtkVolumeProperty
// (ParaView's colouring and lighting), the vtkVolume (its matrix) and the mapper, and what the
// representation reports back (samples, times, memory). One line per property: the
// representation's Set<Name>(value) calls <Target>->Set<Name>(value).
#include "vtkAMRDualMeshRepresentation.h"

#include "AMRDualMeshDataCache.h"
#include "AMRDualMeshRemovedProperties.h"
#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkContourValues.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

#define AMRDM_FORWARD(Target, Name, Type)                                                          \
  void vtkAMRDualMeshRepresentation::Set##Name(Type val)                                           \
  {                                                                                                \
    this->Target->Set##Name(val);                                                                  \
  }
#define AMRDM_FORWARD3(Target, Name)                                                               \
  void vtkAMRDualMeshRepresentation::Set##Name(double x, double y, double z)                       \
  {                                                                                                \
    this->Target->Set##Name(x, y, z);                                                              \
  }

// vtkVolumeProperty: ParaView's colouring and lighting.
AMRDM_FORWARD(Property, Color, vtkColorTransferFunction*)
AMRDM_FORWARD(Property, ScalarOpacity, vtkPiecewiseFunction*)
AMRDM_FORWARD(Property, ScalarOpacityUnitDistance, double)
AMRDM_FORWARD(Property, Shade, bool)
AMRDM_FORWARD(Property, Ambient, double)
AMRDM_FORWARD(Property, Diffuse, double)
AMRDM_FORWARD(Property, Specular, double)
AMRDM_FORWARD(Property, SpecularPower, double)
AMRDM_FORWARD(Property, SliceFunction, vtkImplicitFunction*)
void vtkAMRDualMeshRepresentation::SetIsosurfaceValue(int i, double value)
{
  this->Property->GetIsoSurfaceValues()->SetValue(i, value);
}
void vtkAMRDualMeshRepresentation::SetNumberOfIsosurfaces(int number)
{
  this->Property->GetIsoSurfaceValues()->SetNumberOfContours(number);
}

// vtkVolume: its matrix.
AMRDM_FORWARD3(Volume, Position)
AMRDM_FORWARD3(Volume, Orientation)
AMRDM_FORWARD3(Volume, Scale)
AMRDM_FORWARD3(Volume, Origin)

// vtkAMRDualMeshVolumeMapper: BlendMode (vtkVolumeMapper's), then core/ParameterTable.h's rows.
AMRDM_FORWARD(Mapper, BlendMode, int)
// BEGIN GENERATED representation-forwarders (Tools/generate_parameters.py)
// clang-format off
AMRDM_FORWARD(Mapper, Integrator, int)
AMRDM_FORWARD(Mapper, Device, int)
AMRDM_FORWARD(Mapper, SamplesPerRender, int)
AMRDM_FORWARD(Mapper, MaximumSamples, int)
AMRDM_FORWARD(Mapper, ScatteringAnisotropy, double)
AMRDM_FORWARD3(Mapper, EnvironmentRadiance)
AMRDM_FORWARD(Mapper, EmbedIsosurfaces, int)
AMRDM_FORWARD(Mapper, MaximumBounces, int)
AMRDM_FORWARD(Mapper, StepSize, double)
AMRDM_FORWARD(Mapper, SamplesPerCell, double)
AMRDM_FORWARD(Mapper, ElementTest, int)
AMRDM_FORWARD(Mapper, MaxNewtonIterations, int)
AMRDM_FORWARD(Mapper, GridletSize, int)
AMRDM_FORWARD(Mapper, BVHLeafSize, int)
AMRDM_FORWARD(Mapper, MajorantResolution, int)
AMRDM_FORWARD(Mapper, NumberOfThreads, int)
AMRDM_FORWARD(Mapper, Seed, int)
AMRDM_FORWARD(Mapper, InteractiveFrameTime, double)
AMRDM_FORWARD(Mapper, FinalRenderTime, double)
// clang-format on
// END GENERATED representation-forwarders

// The removed names: remembered, compared with Volume's properties at the next render
// (AMRDualMeshRemovedProperties.h).
void vtkAMRDualMeshRepresentation::SetRemovedPathTracerScalarOpacityUnitDistance(double val)
{
  this->Removed->UnitDistance = val;
}
void vtkAMRDualMeshRepresentation::SetRemovedPathTracerShade(int val)
{
  this->Removed->Shade = val;
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshRepresentation::GetNumberOfSamples()
{
  return this->Mapper->GetNumberOfSamples();
}
double vtkAMRDualMeshRepresentation::GetLastRenderSeconds()
{
  return this->Mapper->GetLastRenderSeconds();
}
double vtkAMRDualMeshRepresentation::GetDualMeshBytes()
{
  return static_cast<double>(this->Mapper->GetDualMesh()->GetTotalBytes());
}
int vtkAMRDualMeshRepresentation::GetRegionIndex()
{
  return this->Data->RegionIndex;
}
double* vtkAMRDualMeshRepresentation::GetDataBounds()
{
  return this->Data->DataBounds;
}
void vtkAMRDualMeshRepresentation::GetDataBounds(double bounds[6])
{
  std::copy(this->Data->DataBounds, this->Data->DataBounds + 6, bounds);
}
double vtkAMRDualMeshRepresentation::GetRedistributionSeconds()
{
  return this->Data->RedistributionSeconds;
}
double vtkAMRDualMeshRepresentation::GetRedistributedBytes()
{
  return this->Data->RedistributedBytes;
}
