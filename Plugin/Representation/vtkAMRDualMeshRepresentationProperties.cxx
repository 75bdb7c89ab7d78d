// vtkAMRDualMeshRepresentation: the properties forwarded unchanged to the vtkVolumeProperty
// (ParaView's colouring and lighting), the vtkVolume (its matrix) and the mapper, and what the
// representation reports back (samples, times, memory).
#include "vtkAMRDualMeshRepresentation.h"

#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <mutex>

//------------------------------------------------------------------------------
// vtkVolumeProperty: ParaView's colouring and lighting.
void vtkAMRDualMeshRepresentation::SetColor(vtkColorTransferFunction* lut)
{
  this->Property->SetColor(lut);
}
void vtkAMRDualMeshRepresentation::SetScalarOpacity(vtkPiecewiseFunction* pwf)
{
  this->Property->SetScalarOpacity(pwf);
}
void vtkAMRDualMeshRepresentation::SetScalarOpacityUnitDistance(double val)
{
  this->Property->SetScalarOpacityUnitDistance(val);
}
void vtkAMRDualMeshRepresentation::SetShade(bool val)
{
  this->Property->SetShade(val);
}
void vtkAMRDualMeshRepresentation::SetPosition(double x, double y, double z)
{
  this->Volume->SetPosition(x, y, z);
}
void vtkAMRDualMeshRepresentation::SetOrientation(double x, double y, double z)
{
  this->Volume->SetOrientation(x, y, z);
}
void vtkAMRDualMeshRepresentation::SetScale(double x, double y, double z)
{
  this->Volume->SetScale(x, y, z);
}
void vtkAMRDualMeshRepresentation::SetOrigin(double x, double y, double z)
{
  this->Volume->SetOrigin(x, y, z);
}
void vtkAMRDualMeshRepresentation::SetAmbient(double val)
{
  this->Property->SetAmbient(val);
}
void vtkAMRDualMeshRepresentation::SetDiffuse(double val)
{
  this->Property->SetDiffuse(val);
}
void vtkAMRDualMeshRepresentation::SetSpecular(double val)
{
  this->Property->SetSpecular(val);
}
void vtkAMRDualMeshRepresentation::SetSpecularPower(double val)
{
  this->Property->SetSpecularPower(val);
}

//------------------------------------------------------------------------------
// The removed names: remembered, compared with Volume's properties at the next render.
void vtkAMRDualMeshRepresentation::SetRemovedPathTracerScalarOpacityUnitDistance(double val)
{
  this->RemovedUnitDistance = val;
}
void vtkAMRDualMeshRepresentation::SetRemovedPathTracerShade(int val)
{
  this->RemovedShade = val;
}
void vtkAMRDualMeshRepresentation::ReportRemovedProperties()
{
  const double unit = this->Property->GetScalarOpacityUnitDistance();
  const double old = this->RemovedUnitDistance;
  if (old > 0.0 && std::abs(old - unit) > 1e-6 * std::max(std::abs(old), std::abs(unit)))
  {
    static std::once_flag said;
    std::call_once(said,
      [&]
      {
        vtkWarningMacro("PathTracerScalarOpacityUnitDistance was removed: the representation "
                        "uses ScalarOpacityUnitDistance (the Volume representation's), now "
                        << unit << "; the value " << old
                        << " of the old name is not used. Set ScalarOpacityUnitDistance = " << old
                        << " for the old picture.");
      });
  }
  if (this->RemovedShade >= 0 && (this->RemovedShade != 0) != (this->Property->GetShade() != 0))
  {
    static std::once_flag said;
    std::call_once(said,
      [&]
      {
        vtkWarningMacro("PathTracerShade was removed: the representation uses Shade (the "
                        "Volume representation's), now "
                        << this->Property->GetShade() << "; the value " << this->RemovedShade
                        << " of the old name is not used. Set Shade = " << this->RemovedShade
                        << " for the old picture.");
      });
  }
}

//------------------------------------------------------------------------------
// vtkAMRDualMeshVolumeMapper.
void vtkAMRDualMeshRepresentation::SetDevice(int val)
{
  this->Mapper->SetDevice(val);
}
void vtkAMRDualMeshRepresentation::SetIntegrator(int val)
{
  this->Mapper->SetIntegrator(val);
}
void vtkAMRDualMeshRepresentation::SetElementTest(int val)
{
  this->Mapper->SetElementTest(val);
}
void vtkAMRDualMeshRepresentation::SetMaxNewtonIterations(int val)
{
  this->Mapper->SetMaxNewtonIterations(val);
}
void vtkAMRDualMeshRepresentation::SetGridletSize(int val)
{
  this->Mapper->SetGridletSize(val);
}
void vtkAMRDualMeshRepresentation::SetBVHLeafSize(int val)
{
  this->Mapper->SetBVHLeafSize(val);
}
void vtkAMRDualMeshRepresentation::SetSamplesPerRender(int val)
{
  this->Mapper->SetSamplesPerRender(val);
}
void vtkAMRDualMeshRepresentation::SetMaximumSamples(int val)
{
  this->Mapper->SetMaximumSamples(val);
}
void vtkAMRDualMeshRepresentation::SetMaximumBounces(int val)
{
  this->Mapper->SetMaximumBounces(val);
}
void vtkAMRDualMeshRepresentation::SetScatteringAnisotropy(double val)
{
  this->Mapper->SetScatteringAnisotropy(val);
}
void vtkAMRDualMeshRepresentation::SetStepSize(double val)
{
  this->Mapper->SetStepSize(val);
}
void vtkAMRDualMeshRepresentation::SetSamplesPerCell(double val)
{
  this->Mapper->SetSamplesPerCell(val);
}
void vtkAMRDualMeshRepresentation::SetMajorantResolution(int val)
{
  this->Mapper->SetMajorantResolution(val);
}
void vtkAMRDualMeshRepresentation::SetNumberOfThreads(int val)
{
  this->Mapper->SetNumberOfThreads(val);
}
void vtkAMRDualMeshRepresentation::SetSeed(int val)
{
  this->Mapper->SetSeed(val);
}
void vtkAMRDualMeshRepresentation::SetEnvironmentRadiance(double r, double g, double b)
{
  this->Mapper->SetEnvironmentRadiance(r, g, b);
}
void vtkAMRDualMeshRepresentation::SetInteractiveFrameTime(double val)
{
  this->Mapper->SetInteractiveFrameTime(val);
}
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
