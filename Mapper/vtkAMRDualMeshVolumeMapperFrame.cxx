// vtkAMRDualMeshVolumeMapper: one frame's products: the kernel's render parameters, the
// accumulation and its reset (AccumulationTime), the samples of a pass and the cheap frame of an
// interactive render.
#include "vtkAMRDualMeshVolumeMapperInternals.h"

#include "AMRDualMeshAbortablePass.h"
#include "AMRDualMeshBlendMode.h"
#include "vtkAMRDualMesh.h"

namespace
{
bool SameView(const amrdm::RenderParams& a, const amrdm::RenderParams& b)
{
  if (!amrdm_vtk::SameRays(a.camera, b.camera) || a.width != b.width || a.height != b.height ||
      a.numLights != b.numLights || a.gradientShading != b.gradientShading ||
      a.ambientCoefficient != b.ambientCoefficient ||
      a.diffuseCoefficient != b.diffuseCoefficient ||
      a.specularCoefficient != b.specularCoefficient || a.specularPower != b.specularPower ||
      !amrdm_vtk::SameBlend(a, b))
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
int vtkAMRDualMeshVolumeMapper::GetEffectiveNumberOfThreads() const
{
  return vtkAMRDualMesh::ResolveNumberOfThreads(this->NumberOfThreads);
}

//------------------------------------------------------------------------------
amrdm::RenderParams vtkAMRDualMeshVolumeMapper::MakeRenderParams(vtkRenderer* ren,
  vtkVolume* vol,
  vtkOverlappingAMR* vtkNotUsed(amr),
  int width,
  int height,
  bool& ok)
{
  ok = true;
  Internals& in = *this->Internal;
  vtkVolumeProperty* property = vol->GetProperty();

  amrdm::RenderParams params;
  params.integrator = static_cast<amrdm::IntegratorType>(this->Integrator);
  // BlendMode, iso values, slice plane (AMRDualMeshBlendMode.h); each deviation said once.
  const std::string blend =
    amrdm_vtk::ApplyBlendMode(this, property, in.MeshInRenderer->sceneOrigin, params);
  if (!blend.empty() && blend != in.BlendWarning)
  {
    vtkWarningMacro(<< blend);
  }
  in.BlendWarning = blend;
  params.maxBounces = this->MaximumBounces;
  params.rouletteStartBounce = std::min(params.rouletteStartBounce, this->MaximumBounces);
  params.anisotropy = float(this->ScatteringAnisotropy);
  params.seed = in.Region.SeedFor(static_cast<std::uint32_t>(this->Seed),
    !amrdm::integratorInfo(params.integrator).jitterLattice);
  // 0 = automatic: the renderer's scene resolves it from the dual mesh's domain box, the whole
  // domain also when this process draws one region of N (amrdm::autoStepSize).
  params.stepSize = float(this->StepSize);
  params.samplesPerCell = float(this->SamplesPerCell);
  params.gradientShading = property->GetShade(0) != 0;
  params.ambientCoefficient = float(property->GetAmbient(0));
  params.diffuseCoefficient = float(property->GetDiffuse(0));
  params.specularCoefficient = float(property->GetSpecular(0));
  params.specularPower = float(property->GetSpecularPower(0));
  params.majorantResolution = glm::ivec3(this->MajorantResolution);
  params.elementTest.test = this->ElementTest == ELEMENT_TEST_PLANAR_FACES
                              ? amrdm::ElementTest::PlanarFaces
                              : amrdm::ElementTest::Bilinear;
  params.elementTest.maxNewtonIterations = this->MaxNewtonIterations;
  int usedLights = 0;
  const glm::dvec3 sceneOrigin = in.MeshInRenderer->sceneOrigin; // the scene frame
  const int foundLights =
    amrdm_vtk::MakeLights(ren, params.lights, amrdm::kMaxLights, usedLights, sceneOrigin);
  params.numLights = usedLights;
  if (foundLights > usedLights && !in.WarnedLights)
  {
    // Never for VTK's or ParaView's light kit (5 lights): only scenes with more lights than
    // the kernel's slots are told what is dropped.
    vtkWarningMacro("The renderer has " << foundLights << " lights switched on; the first "
                                        << amrdm::kMaxLights << " are used, the other "
                                        << foundLights - usedLights << " are ignored.");
    in.WarnedLights = true;
  }
  params.ambient = glm::vec3(
    this->EnvironmentRadiance[0], this->EnvironmentRadiance[1], this->EnvironmentRadiance[2]);
  // Rays of the projection VTK draws this (tiled) viewport with, in the volume's data frame.
  double ndcToScene[16];
  vtkMatrix4x4* model = vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix();
  if (!amrdm_vtk::NdcToScene(ren, model, sceneOrigin, ndcToScene))
  {
    vtkErrorMacro("The camera's projection composed with the vtkVolume's matrix is singular "
                  "(e.g. a scale of 0); expected an invertible volume matrix.");
    ok = false;
    return params;
  }
  params.camera = amrdm_vtk::MakeCamera(ren, ndcToScene);
  params.camera.anchor = glm::vec3(amrdm_vtk::CameraAnchor(ren, model, sceneOrigin));
  if (in.Region.Active())
  {
    // Every (jittered) camera ray is cut exactly at the region's faces, in the data's frame.
    params.clipToBox = true;
    for (int d = 0; d < 3; ++d)
    {
      params.clipLo[d] = float(in.Region.Bounds[2 * d] - sceneOrigin[d]);
      params.clipHi[d] = float(in.Region.Bounds[2 * d + 1] - sceneOrigin[d]);
    }
  }
  if (model)
  {
    amrdm_vtk::LightsToDataFrame(model, sceneOrigin, params.lights, params.numLights);
  }
  params.width = width;
  params.height = height;
  params.threads = this->GetEffectiveNumberOfThreads();
  return params;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::UpdateAccumulation(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm::RenderParams& params,
  const int viewport[4],
  bool& reset)
{
  Internals& in = *this->Internal;
  const int x0 = viewport[0], y0 = viewport[1], width = viewport[2], height = viewport[3];
  // Per-pixel ray intervals from the opaque depth and the clipping planes.
  std::vector<float> depth;
  in.Compositor.ReadDepth(ren, x0, y0, width, height, depth);
  const glm::dvec3 sceneOrigin = in.MeshInRenderer->sceneOrigin;
  vtkMatrix4x4* model = vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix();
  double ndcToScene[16];
  const bool invertible = amrdm_vtk::NdcToScene(ren, model, sceneOrigin, ndcToScene);
  std::vector<float> tMin, tMax;
  amrdm_vtk::ComputeRayIntervals(params.camera,
    width,
    height,
    invertible ? depth.data() : nullptr,
    ndcToScene,
    this->ClippingPlanes,
    model,
    sceneOrigin,
    tMin,
    tMax);
  // Depth re-read by a re-render (a screenshot) may differ in the last bits: intervals within
  // a thousandth of the finest cell are the same.
  const glm::dvec3 h = in.MeshInRenderer->finestSpacing;
  const float tolerance = float(1e-3 * std::min({ h.x, h.y, h.z }));

  // The accumulation follows everything: parameters and property by MTime, the view, lights,
  // size and per-pixel intervals by value.
  vtkMTimeType configTime = std::max(this->GetMTime(), vol->GetProperty()->GetMTime());
  if (this->ClippingPlanes)
  {
    vtkCollectionSimpleIterator it;
    this->ClippingPlanes->InitTraversal(it);
    while (vtkPlane* plane = this->ClippingPlanes->GetNextPlane(it))
    {
      configTime = std::max(configTime, plane->GetMTime());
    }
  }
  reset = !in.HasAccumulation || configTime > this->AccumulationTime.GetMTime() ||
          !SameView(params, in.Params) ||
          !amrdm_vtk::SameIntervals(tMin, tMax, in.TMin, in.TMax, tolerance);
  if (reset)
  {
    in.Renderer->reset();
    in.Samples = 0;
    in.Params = params;
    in.TMin.swap(tMin);
    in.TMax.swap(tMax);
    in.HasAccumulation = true;
    this->AccumulationTime.Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::AddSamples(amrdm::RenderParams params,
  bool reset,
  vtkRenderWindow* window)
{
  Internals& in = *this->Internal;
  int limit = this->MaximumSamples;
  if (in.SampleLimit > 0)
  {
    limit = std::min(limit, in.SampleLimit);
  }
  if (in.Samples >= limit && !reset)
  {
    return true; // converged: only re-composite
  }
  params.samplesPerPass = std::max(1, std::min(this->SamplesPerRender, limit - in.Samples));
  try
  {
    const auto start = std::chrono::steady_clock::now();
    if (amrdm_vtk::RenderAbortablePass(
          *in.Renderer, params, in.TMax.data(), in.TMin.data(), window) ==
        amrdm_vtk::PassOutcome::Completed)
    {
      in.Samples += params.samplesPerPass;
      // The cost per pixel sample sizes the next interactive frame.
      in.Interaction.RecordPass(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        double(params.width) * params.height * params.samplesPerPass);
    }
    else
    {
      in.LastRenderAborted = true; // finished tiles kept their samples: the mean stays valid
    }
    in.Image = in.Renderer->image();
  }
  catch (const std::exception& e) // e.g. accumulation buffers larger than the free memory
  {
    vtkErrorMacro(
      "Cannot render a " << params.width << " x " << params.height << " image: " << e.what());
    in.HasAccumulation = false;
    in.Image.clear();
    return false;
  }
  in.ImageSize[0] = params.width;
  in.ImageSize[1] = params.height;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::RenderInteractiveFrame(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm::RenderParams& params,
  const int viewport[4])
{
  // One cheap frame (AMRDualMeshInteraction.h); the next still render restarts the accumulation.
  Internals& in = *this->Internal;
  in.HasAccumulation = false;
  in.Samples = 0;
  std::string error;
  if (!in.Interaction.RenderFrame(ren,
        *in.Renderer,
        in.Compositor,
        params,
        viewport,
        this->ClippingPlanes,
        vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix(),
        in.MeshInRenderer->sceneOrigin,
        this->InteractiveFrameTime,
        in.InteractiveReduction,
        error))
  {
    vtkErrorMacro("Cannot render an interactive frame: " << error);
    return false;
  }
  return true;
}
