// The scene shared by the volume-mapper tests: the AMReX advection set (phi, three levels), a
// cool-to-warm colour function, an opacity ramp that leaves the background phi = 1 faintly
// visible, a camera looking down at the blob, an opaque sphere half inside the slab and two
// clipping planes (x <= 0.76 and y >= 0.42 are kept).
#pragma once

#include "RealData.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkVolumeProperty.h"

namespace amrdm_test
{
inline vtkSmartPointer<vtkOverlappingAMR> readAdvection()
{
  for (const RealSet& set : realSets())
  {
    if (set.name == "amrex-advection" && !set.path.empty())
    {
      return readSet(set);
    }
  }
  return nullptr;
}

inline vtkSmartPointer<vtkVolumeProperty> advectionProperty()
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(1.0, 0.23, 0.30, 0.75);
  color->AddRGBPoint(1.5, 0.87, 0.87, 0.87);
  color->AddRGBPoint(2.0, 0.71, 0.02, 0.15);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(1.0, 0.0);
  opacity->AddPoint(1.02, 0.01);
  opacity->AddPoint(1.3, 0.3);
  opacity->AddPoint(2.0, 0.9);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.02);
  return property;
}

inline vtkSmartPointer<vtkPlaneCollection> advectionPlanes()
{
  auto planes = vtkSmartPointer<vtkPlaneCollection>::New();
  vtkNew<vtkPlane> x, y;
  x->SetOrigin(0.76, 0.5, 0.5);
  x->SetNormal(-1.0, 0.0, 0.0);
  y->SetOrigin(0.5, 0.42, 0.5);
  y->SetNormal(0.0, 1.0, 0.0);
  planes->AddItem(x);
  planes->AddItem(y);
  return planes;
}

/// The opaque sphere: centre on the slab's top face (z = 0.25), so half of it is inside.
inline vtkSmartPointer<vtkActor> advectionSphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.64, 0.52, 0.25);
  sphere->SetRadius(0.1);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  return actor;
}

inline void advectionCamera(vtkRenderer* ren)
{
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetFocalPoint(0.68, 0.56, 0.12);
  cam->SetPosition(0.98, -0.24, 0.82);
  cam->SetViewUp(0.0, 0.0, 1.0);
  ren->ResetCameraClippingRange();
}
}
