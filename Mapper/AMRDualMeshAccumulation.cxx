#include "AMRDualMeshAccumulation.h"

#include "AMRDualMeshBlendMode.h"
#include "AMRDualMeshProjection.h"
#include "vtkCollection.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "render/Renderer.h"

#include <algorithm>

namespace amrdm_vtk
{
namespace
{
bool SameView(const amrdm::RenderParams& a, const amrdm::RenderParams& b)
{
  if (!amrdm_vtk::SameRays(a.camera, b.camera) || a.width != b.width || a.height != b.height ||
      a.numLights != b.numLights || a.gradientShading != b.gradientShading ||
      a.ambientCoefficient != b.ambientCoefficient ||
      a.diffuseCoefficient != b.diffuseCoefficient ||
      a.specularCoefficient != b.specularCoefficient || a.specularPower != b.specularPower ||
      !SameBlend(a, b))
  {
    return false;
  }
  for (int i = 0; i < a.numLights; ++i)
  {
    const amrdm::Light &la = a.lights[i], &lb = b.lights[i];
    if (la.type != lb.type || la.direction != lb.direction || la.position != lb.position ||
        la.color != lb.color || la.intensity != lb.intensity)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkMTimeType AccumulationConfigTime(vtkObject* mapper, vtkVolume* vol, vtkPlaneCollection* planes)
{
  // Parameters and property by MTime (the view, lights, size and intervals are compared by value).
  vtkMTimeType time = std::max(mapper->GetMTime(), vol->GetProperty()->GetMTime());
  if (planes)
  {
    vtkCollectionSimpleIterator it;
    planes->InitTraversal(it);
    while (vtkPlane* plane = planes->GetNextPlane(it))
    {
      time = std::max(time, plane->GetMTime());
    }
  }
  return time;
}

//------------------------------------------------------------------------------
bool Accumulation::Update(AccumulationKey& key, amrdm::Renderer& renderer)
{
  const vtkMTimeType started = this->Time.GetMTime();
  const bool reset =
    !this->Valid || key.ConfigTime > started || key.SlotTime > started ||
    !SameView(key.Params, this->Key.Params) ||
    !amrdm_vtk::SameIntervals(key.TMin, key.TMax, this->Key.TMin, this->Key.TMax, key.Tolerance);
  if (reset)
  {
    renderer.reset();
    this->Samples = 0;
    std::swap(this->Key, key);
    this->Valid = true;
    this->Time.Modified();
  }
  return reset;
}

//------------------------------------------------------------------------------
vtkMTimeType Accumulation::ClientKey(const AccumulationKey& key)
{
  if (!this->HasClient || key.ConfigTime > this->ClientTime.GetMTime() ||
      !SameView(key.Params, this->Client.Params))
  {
    this->Client.Params = key.Params;
    this->HasClient = true;
    this->ClientTime.Modified();
  }
  return this->ClientTime.GetMTime();
}
}
