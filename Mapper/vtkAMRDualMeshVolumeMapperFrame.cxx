// vtkAMRDualMeshVolumeMapper: one frame's products: the kernel's render parameters, the
// accumulation's reset key (AMRDualMeshAccumulation.h), the samples of a pass, the cheap frame of
// an interactive render and the accumulated image's EXR file.
#include "vtkAMRDualMeshVolumeMapperInternals.h"

#include "AMRDualMeshAbortablePass.h"
#include "AMRDualMeshBlendMode.h"
#include "vtkAMRDualMesh.h"

//------------------------------------------------------------------------------
int vtkAMRDualMeshVolumeMapper::GetEffectiveNumberOfThreads() const
{
  return vtkAMRDualMesh::ResolveNumberOfThreads(this->NumberOfThreads);
}

//------------------------------------------------------------------------------
amrdm::RenderParams vtkAMRDualMeshVolumeMapper::MakeRenderParams(vtkRenderer* ren,
  vtkVolume* vol,
  const double origin[3],
  int width,
  int height,
  bool& ok,
  bool report)
{
  ok = true;
  Internals& in = *this->Internal;
  vtkVolumeProperty* property = vol->GetProperty();

  amrdm::RenderParams params;
  params.integrator = static_cast<amrdm::IntegratorType>(this->Integrator);
  // BlendMode, iso values, slice plane (AMRDualMeshBlendMode.h); each deviation said once.
  const std::string blend =
    amrdm_vtk::ApplyBlendMode(this, property, glm::dvec3(origin[0], origin[1], origin[2]), params);
  if (report && !blend.empty() && blend != in.BlendWarning)
  {
    vtkWarningMacro(<< blend);
  }
  in.BlendWarning = report ? blend : in.BlendWarning;
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
  const glm::dvec3 sceneOrigin(origin[0], origin[1], origin[2]); // the scene frame
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
    ok = false;
    if (!report)
    {
      return params;
    }
    vtkErrorMacro("The camera's projection composed with the vtkVolume's matrix is singular "
                  "(e.g. a scale of 0); expected an invertible volume matrix.");
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

  // The accumulation follows everything (AMRDualMeshAccumulation.h).
  amrdm_vtk::AccumulationKey key;
  key.ConfigTime = amrdm_vtk::AccumulationConfigTime(this, vol, this->ClippingPlanes);
  key.Params = params;
  key.TMin.swap(tMin);
  key.TMax.swap(tMax);
  key.Tolerance = tolerance;
  reset = in.Accum.Update(key, *in.Renderer);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAMRDualMeshVolumeMapper::GetAccumulationKey(vtkRenderer* ren, vtkVolume* vol)
{
  // The key of a frame without its render-time parts (slot stamps, opaque depth), in a scene
  // frame at the origin (a fixed frame: only changes count).
  amrdm_vtk::AccumulationKey key;
  if (!ren || !vol || !vol->GetProperty())
  {
    return 0;
  }
  int size[2] = { 0, 0 }, origin[2] = { 0, 0 };
  ren->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  const double sceneOrigin[3] = { 0.0, 0.0, 0.0 };
  bool ok = true;
  key.Params = this->MakeRenderParams(ren, vol, sceneOrigin, size[0], size[1], ok, false);
  key.ConfigTime = amrdm_vtk::AccumulationConfigTime(this, vol, this->ClippingPlanes);
  return this->Internal->Accum.ClientKey(key);
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
  if (in.Accum.Samples >= limit && !reset)
  {
    return true; // converged: only re-composite
  }
  params.samplesPerPass = std::max(1, std::min(this->SamplesPerRender, limit - in.Accum.Samples));
  try
  {
    const auto start = std::chrono::steady_clock::now();
    if (amrdm_vtk::RenderAbortablePass(
          *in.Renderer, params, in.Accum.GetTMax(), in.Accum.GetTMin(), window) ==
        amrdm_vtk::PassOutcome::Completed)
    {
      in.Accum.Samples += params.samplesPerPass;
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
    in.Accum.Invalidate();
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
  in.Accum.Invalidate();
  in.Accum.Samples = 0;
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

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::WriteLastImageEXR(const char* fileName)
{
  const Internals& in = *this->Internal;
  if (!fileName || in.Image.empty())
  {
    vtkErrorMacro("WriteLastImageEXR(): " << (fileName ? "nothing rendered yet" : "no file name"));
    return false;
  }
  std::string error;
  if (!amrdm_vtk::WriteEXR(fileName, in.ImageSize[0], in.ImageSize[1], in.Image.data(), error))
  {
    vtkErrorMacro("WriteLastImageEXR(): " << error);
    return false;
  }
  return true;
}
