#include "AMRDualMeshFrameBuilder.h"

#include "AMRDualMeshBlendMode.h"
#include "AMRDualMeshCompositor.h"
#include "AMRDualMeshPointSampling.h"
#include "AMRDualMeshProjection.h"
#include "AMRDualMeshRegion.h"
#include "AMRDualMeshSceneConversion.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "mesh/DualMesh.h"
#include "render/IntegratorList.h"

#include <algorithm>
#include <vector>

// The mapper's constants are the rows of the kernels' integrator list.
static_assert(
  vtkAMRDualMeshVolumeMapper::PATH_TRACER == int(amrdm::IntegratorType::PathTracer) &&
    vtkAMRDualMeshVolumeMapper::SINGLE_SCATTER == int(amrdm::IntegratorType::SingleScatter) &&
    vtkAMRDualMeshVolumeMapper::RAY_MARCH == int(amrdm::IntegratorType::RayMarch) &&
    vtkAMRDualMeshVolumeMapper::DEBUG_PRIMITIVES == int(amrdm::IntegratorType::DebugPrimitive) &&
    vtkAMRDualMeshVolumeMapper::DEBUG_COST == int(amrdm::IntegratorType::DebugCost),
  "vtkAMRDualMeshVolumeMapper::Integrators differ from render/IntegratorList.h");

namespace amrdm_vtk
{
namespace
{
/// field = the mapper's value in the kernel field's type (an enumeration, float, the unsigned
/// seed, an ivec3 of one value); the generated frame-params block calls it for every Render row.
template<typename Field, typename Value>
void FromMapper(Field& field, Value value)
{
  field = static_cast<Field>(value);
}
/// The ElementTest row through the module's one conversion.
void FromMapper(amrdm::ElementTest& field, int value)
{
  field = ToElementTest(value);
}
/// A Double3 row (RGB) into a glm::vec3.
void FromMapper(glm::vec3& field, double* value) // vtkGetVector3Macro returns double*
{
  field = glm::vec3(value[0], value[1], value[2]);
}
} // namespace
} // namespace amrdm_vtk

//------------------------------------------------------------------------------
bool AMRDualMeshFrameBuilder::MakeParams(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm_vtk::RegionClip& region,
  const double origin[3],
  int width,
  int height,
  bool report,
  amrdm::RenderParams& params)
{
  vtkAMRDualMeshVolumeMapper* mapper = this->Mapper;
  vtkVolumeProperty* property = vol->GetProperty();

  params = amrdm::RenderParams();
  // The Render rows of the parameter table (core/ParameterTable.h), converted to the kernel
  // field's type; the adjustments below (seed per region, roulette, blend state) start from them.
  // BEGIN GENERATED frame-params (Tools/generate_parameters.py)
  // clang-format off
  amrdm_vtk::FromMapper(params.integrator, mapper->GetIntegrator());
  amrdm_vtk::FromMapper(params.anisotropy, mapper->GetScatteringAnisotropy());
  amrdm_vtk::FromMapper(params.ambient, mapper->GetEnvironmentRadiance());
  amrdm_vtk::FromMapper(params.embedIsosurfaces, mapper->GetEmbedIsosurfaces());
  amrdm_vtk::FromMapper(params.maxBounces, mapper->GetMaximumBounces());
  amrdm_vtk::FromMapper(params.stepSize, mapper->GetStepSize());
  amrdm_vtk::FromMapper(params.samplesPerCell, mapper->GetSamplesPerCell());
  amrdm_vtk::FromMapper(params.elementTest.test, mapper->GetElementTest());
  amrdm_vtk::FromMapper(params.elementTest.maxNewtonIterations, mapper->GetMaxNewtonIterations());
  amrdm_vtk::FromMapper(params.majorantResolution, mapper->GetMajorantResolution());
  amrdm_vtk::FromMapper(params.seed, mapper->GetSeed());
  // clang-format on
  // END GENERATED frame-params
  // BlendMode, iso values, slice plane (AMRDualMeshBlendMode.h); each deviation said once.
  const std::string blend = amrdm_vtk::ApplyBlendMode(
    mapper, property, glm::dvec3(origin[0], origin[1], origin[2]), params);
  if (report && !blend.empty() && blend != this->BlendWarning)
  {
    vtkWarningWithObjectMacro(mapper, << blend);
  }
  this->BlendWarning = report ? blend : this->BlendWarning;
  params.rouletteStartBounce = std::min(params.rouletteStartBounce, params.maxBounces);
  params.seed =
    region.SeedFor(params.seed, !amrdm::integratorInfo(params.integrator).jitterLattice);
  // stepSize 0 = automatic: the renderer's scene resolves it from the dual mesh's domain box, the
  // whole domain also when this process draws one region of N (amrdm::autoStepSize).
  params.gradientShading = property->GetShade(0) != 0;
  params.ambientCoefficient = float(property->GetAmbient(0));
  params.diffuseCoefficient = float(property->GetDiffuse(0));
  params.specularCoefficient = float(property->GetSpecular(0));
  params.specularPower = float(property->GetSpecularPower(0));
  int usedLights = 0;
  const glm::dvec3 sceneOrigin(origin[0], origin[1], origin[2]); // the scene frame
  const int foundLights =
    amrdm_vtk::MakeLights(ren, params.lights, amrdm::kMaxLights, usedLights, sceneOrigin);
  params.numLights = usedLights;
  if (foundLights > usedLights && !this->WarnedLights)
  {
    // Never for VTK's or ParaView's light kit (5 lights): only scenes with more lights than
    // the kernel's slots are told what is dropped.
    vtkWarningWithObjectMacro(mapper,
      "The renderer has " << foundLights << " lights switched on; the first " << amrdm::kMaxLights
                          << " are used, the other " << foundLights - usedLights
                          << " are ignored.");
    this->WarnedLights = true;
  }
  // Rays of the projection VTK draws this (tiled) viewport with, in the volume's data frame.
  double ndcToScene[16];
  vtkMatrix4x4* model = vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix();
  if (!amrdm_vtk::NdcToScene(ren, model, sceneOrigin, ndcToScene))
  {
    if (!report)
    {
      return false;
    }
    vtkErrorWithObjectMacro(mapper,
      "The camera's projection composed with the vtkVolume's matrix is singular "
      "(e.g. a scale of 0); expected an invertible volume matrix.");
    return false;
  }
  params.camera = amrdm_vtk::MakeCamera(ren, ndcToScene);
  params.camera.anchor = glm::vec3(amrdm_vtk::CameraAnchor(ren, model, sceneOrigin));
  if (region.Active())
  {
    // Every (jittered) camera ray is cut exactly at the region's faces, in the data's frame.
    params.clipToBox = true;
    for (int d = 0; d < 3; ++d)
    {
      params.clipLo[d] = float(region.Bounds[2 * d] - sceneOrigin[d]);
      params.clipHi[d] = float(region.Bounds[2 * d + 1] - sceneOrigin[d]);
    }
  }
  if (model)
  {
    amrdm_vtk::LightsToDataFrame(model, sceneOrigin, params.lights, params.numLights);
  }
  params.width = width;
  params.height = height;
  params.threads = mapper->GetEffectiveNumberOfThreads();
  return true;
}

//------------------------------------------------------------------------------
void AMRDualMeshFrameBuilder::MakeKey(vtkRenderer* ren,
  vtkVolume* vol,
  amrdm_vtk::Compositor& compositor,
  const amrdm::DualMesh& mesh,
  const amrdm::RenderParams& params,
  const int viewport[4],
  vtkMTimeType slotTime,
  amrdm_vtk::AccumulationKey& key)
{
  const int x0 = viewport[0], y0 = viewport[1], width = viewport[2], height = viewport[3];
  // Per-pixel ray intervals from the opaque depth and the clipping planes.
  std::vector<float> depth;
  compositor.ReadDepth(ren, x0, y0, width, height, depth);
  const glm::dvec3 sceneOrigin = mesh.sceneOrigin;
  vtkMatrix4x4* model = vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix();
  double ndcToScene[16];
  const bool invertible = amrdm_vtk::NdcToScene(ren, model, sceneOrigin, ndcToScene);
  std::vector<float> tMin, tMax;
  amrdm_vtk::ComputeRayIntervals(params.camera,
    width,
    height,
    invertible ? depth.data() : nullptr,
    ndcToScene,
    this->Mapper->GetClippingPlanes(),
    model,
    sceneOrigin,
    tMin,
    tMax);
  // Depth re-read by a re-render (a screenshot) may differ in the last bits: intervals within
  // a thousandth of the finest cell are the same.
  const glm::dvec3 h = mesh.finestSpacing;
  const float tolerance = float(1e-3 * std::min({ h.x, h.y, h.z }));

  // The accumulation follows everything (AMRDualMeshAccumulation.h).
  key.ConfigTime =
    amrdm_vtk::AccumulationConfigTime(this->Mapper, vol, this->Mapper->GetClippingPlanes());
  key.Params = params;
  key.TMin.swap(tMin);
  key.TMax.swap(tMax);
  key.Tolerance = tolerance;
  key.SlotTime = slotTime;
}

//------------------------------------------------------------------------------
void AMRDualMeshFrameBuilder::MakeClientKey(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm_vtk::RegionClip& region,
  amrdm_vtk::AccumulationKey& key)
{
  int size[2] = { 0, 0 }, corner[2] = { 0, 0 };
  ren->GetTiledSizeAndOrigin(&size[0], &size[1], &corner[0], &corner[1]);
  const double origin[3] = { 0.0, 0.0, 0.0 };
  this->MakeParams(ren, vol, region, origin, size[0], size[1], false, key.Params);
  key.ConfigTime =
    amrdm_vtk::AccumulationConfigTime(this->Mapper, vol, this->Mapper->GetClippingPlanes());
}
