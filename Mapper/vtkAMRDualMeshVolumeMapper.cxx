#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshCompositor.h"
#include "AMRDualMeshImageIO.h"
#include "AMRDualMeshInteraction.h"
#include "AMRDualMeshProjection.h"
#include "AMRDualMeshSceneConversion.h"
#include "vtkAMRDualMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkOverlappingAMR.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUniformGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "DualMesh.h"
#include "RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <mutex>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkAMRDualMeshVolumeMapper);

struct vtkAMRDualMeshVolumeMapper::Internals
{
  vtkNew<vtkAMRDualMesh> Mesh;
  vtkNew<vtkCallbackCommand> ProgressForwarder;
  vtkNew<vtkCallbackCommand> ErrorCatcher;
  std::string MeshError; ///< last error reported by the dual mesh
  std::string InputError; ///< the last point-data refusal (said once per array)

  std::unique_ptr<amrdm::Renderer> Renderer; ///< created for Device by UpdateRenderer()
  int RendererDevice = -1;                    ///< the Device it was created for
  std::string DeviceError;                    ///< why the last creation failed (said once)
  std::string DeviceReport;                   ///< the factory's last line (device chosen, why)
  amrdm_vtk::Compositor Compositor;
  const amrdm::DualMesh* MeshInRenderer = nullptr;
  vtkMTimeType MeshBuildTime = 0;

  // Transfer function currently in the renderer, and what it was sampled from.
  amrdm::TransferFunction Tf;
  bool HasTf = false;
  vtkVolumeProperty* TfProperty = nullptr;
  const void* TfFunctions[2] = { nullptr, nullptr };
  std::string TfWarning; ///< the last transfer-function warning (said once)

  // What the current accumulation was rendered with.
  amrdm::RenderParams Params;
  std::vector<float> Depth, TMin, TMax;
  int Samples = 0;
  bool HasAccumulation = false;
  int ViewSamples = 0;            ///< samples of the last untiled view: what screenshot tiles get
  int ViewSize[2] = { 0, 0 };     ///< its size

  std::vector<float> Image; ///< mean premultiplied RGBA of the accumulation
  int ImageSize[2] = { 0, 0 };

  amrdm_vtk::InteractionPolicy Interaction; ///< interactive frames: reduction from timed passes
  bool LastRenderInteractive = false;
  int InteractiveReduction = 1; ///< of the last interactive frame

  int SampleLimit = 0; ///< > 0 during RenderUntil(): no pass goes beyond it
  int RenderCount = 0; ///< Render() calls (RenderUntil() notices when none happens)
  bool LastRenderOk = false;
  bool WarnedLights = false, WarnedBlend = false;

  static void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<vtkAMRDualMeshVolumeMapper*>(clientData);
    if (callData)
    {
      self->UpdateProgress(*static_cast<double*>(callData));
    }
  }
  static void CatchError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<Internals*>(clientData);
    self->MeshError = callData ? static_cast<const char*>(callData) : "unknown error";
  }
};

namespace
{
bool SameView(const amrdm::RenderParams& a, const amrdm::RenderParams& b)
{
  if (!amrdm_vtk::SameRays(a.camera, b.camera) || a.width != b.width || a.height != b.height ||
      a.numLights != b.numLights || a.gradientShading != b.gradientShading ||
      a.ambientCoefficient != b.ambientCoefficient ||
      a.diffuseCoefficient != b.diffuseCoefficient ||
      a.specularCoefficient != b.specularCoefficient || a.specularPower != b.specularPower)
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
vtkAMRDualMeshVolumeMapper::vtkAMRDualMeshVolumeMapper()
  : Internal(new Internals)
{
  Internals& in = *this->Internal;
  in.ProgressForwarder->SetCallback(&Internals::ForwardProgress);
  in.ProgressForwarder->SetClientData(this);
  in.Mesh->AddObserver(vtkCommand::ProgressEvent, in.ProgressForwarder);
  in.ErrorCatcher->SetCallback(&Internals::CatchError);
  in.ErrorCatcher->SetClientData(&in);
  in.Mesh->AddObserver(vtkCommand::ErrorEvent, in.ErrorCatcher);
}

vtkAMRDualMeshVolumeMapper::~vtkAMRDualMeshVolumeMapper() = default;

const char* vtkAMRDualMeshVolumeMapper::GetDeviceAsString()
{
  switch (this->Device)
  {
    case DEVICE_CPU:
      return "CPU";
    case DEVICE_CUDA:
      return "CUDA";
    default:
      return "AUTO";
  }
}

const char* vtkAMRDualMeshVolumeMapper::GetDeviceReport()
{
  return this->Internal->DeviceReport.c_str();
}

int vtkAMRDualMeshVolumeMapper::GetRenderingDevice()
{
  const Internals& in = *this->Internal;
  if (!in.Renderer)
  {
    return -1;
  }
  return in.Renderer->device() == amrdm::RenderDevice::Cuda ? DEVICE_CUDA : DEVICE_CPU;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::SetInputData(vtkOverlappingAMR* amr)
{
  this->SetInputDataInternal(0, amr);
}

int vtkAMRDualMeshVolumeMapper::FillInputPortInformation(int vtkNotUsed(port), vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOverlappingAMR");
  return 1;
}

vtkAMRDualMesh* vtkAMRDualMeshVolumeMapper::GetDualMesh()
{
  return this->Internal->Mesh;
}

int vtkAMRDualMeshVolumeMapper::GetNumberOfSamples()
{
  return this->Internal->Samples;
}

bool vtkAMRDualMeshVolumeMapper::GetLastRenderInteractive()
{
  return this->Internal->LastRenderInteractive;
}

int vtkAMRDualMeshVolumeMapper::GetInteractiveReduction()
{
  return this->Internal->InteractiveReduction;
}

//------------------------------------------------------------------------------
vtkOverlappingAMR* vtkAMRDualMeshVolumeMapper::UpdateAndGetInput()
{
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    return nullptr;
  }
  vtkDataObject* data = this->GetInputDataObject(0, 0);
  // A data object of the wrong type is refused before the pipeline sees it.
  if (data && !vtkOverlappingAMR::SafeDownCast(data))
  {
    return nullptr;
  }
  if (vtkAlgorithm* producer = this->GetInputAlgorithm())
  {
    producer->Update();
  }
  return vtkOverlappingAMR::SafeDownCast(this->GetInputDataObject(0, 0));
}

double* vtkAMRDualMeshVolumeMapper::GetBounds()
{
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    // vtkVolume skips Render() without input, so the renderer's bounds query reports it.
    vtkErrorMacro("No input: call SetInputData(vtkOverlappingAMR*) or SetInputConnection().");
  }
  vtkOverlappingAMR* amr = this->UpdateAndGetInput();
  if (!amr || !amrdm_vtk::FirstBlock(amr))
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
  else
  {
    amr->GetBounds(this->Bounds);
  }
  return this->Bounds;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateDualMesh(vtkOverlappingAMR* amr)
{
  Internals& in = *this->Internal;
  if (!amrdm_vtk::FirstBlock(amr))
  {
    vtkErrorMacro(
      "The vtkOverlappingAMR input is empty (no blocks with cells); nothing to render.");
    return false;
  }
  // The array, chosen the VTK way; vertex-centred arrays are refused by name, with what works
  // instead (said once per message).
  std::string array, message;
  switch (amrdm_vtk::SelectCellArray(amr, this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
    this->ArrayName, array, message))
  {
    case amrdm_vtk::ArraySelection::PointData:
      if (message != in.InputError)
      {
        vtkErrorMacro(<< message);
        in.InputError = message;
      }
      return false;
    case amrdm_vtk::ArraySelection::Missing:
      vtkErrorMacro(<< message);
      return false;
    case amrdm_vtk::ArraySelection::Chosen:
      break;
  }
  in.InputError.clear();

  vtkAMRDualMesh* mesh = in.Mesh;
  if (mesh->GetInputData() != amr)
  {
    mesh->SetInputData(amr);
  }
  if (!mesh->GetArrayName() || array != mesh->GetArrayName())
  {
    mesh->SetArrayName(array.c_str());
  }
  mesh->SetGridletSize(this->GridletSize);
  mesh->SetNumberOfThreads(this->NumberOfThreads);
  in.MeshError.clear();
  if (!mesh->Update())
  {
    vtkErrorMacro("Cannot build the dual mesh of '" << array << "': " << in.MeshError);
    in.MeshInRenderer = nullptr;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateRenderer()
{
  Internals& in = *this->Internal;
  if (!in.Renderer || in.RendererDevice != this->Device)
  {
    in.Renderer.reset();
    in.MeshInRenderer = nullptr;
    in.HasTf = false;
    in.HasAccumulation = false;
    try
    {
      // The factory's line (which device and why; a fallback) goes to DeviceReport and, once per
      // process and text, to the output window as plain text: not a warning, so that a
      // ParaView view does not pop up a dialog for the expected CPU choice.
      in.DeviceReport.clear();
      in.Renderer = amrdm::createRenderer(static_cast<amrdm::RenderDevice>(this->Device),
        [&in](const std::string& line)
        {
          in.DeviceReport = line;
          static std::mutex mutex;
          static std::set<std::string> said;
          std::lock_guard<std::mutex> lock(mutex);
          if (said.insert(line).second)
          {
            vtkOutputWindowDisplayText(("vtkAMRDualMeshVolumeMapper: " + line + "\n").c_str());
          }
        });
      in.DeviceError.clear();
    }
    catch (const std::exception& e)
    {
      const std::string error = e.what();
      if (error != in.DeviceError)
      {
        vtkErrorMacro("Device " << this->GetDeviceAsString() << ": " << error
                                << " (use Device AUTO or CPU).");
        in.DeviceError = error;
      }
      return false;
    }
    in.RendererDevice = this->Device;
  }
  vtkAMRDualMesh* mesh = in.Mesh;
  if (mesh->GetDualMesh() != in.MeshInRenderer || mesh->GetBuildTime() != in.MeshBuildTime)
  {
    const int r = this->MajorantResolution;
    try
    {
      in.Renderer->setMesh(mesh->GetDualMesh(), glm::ivec3(r), this->NumberOfThreads);
    }
    catch (const std::exception& e) // e.g. a device out of memory with Device CUDA
    {
      vtkErrorMacro("Cannot upload the dual mesh to the " << this->GetDeviceAsString()
                                                          << " renderer: " << e.what());
      in.Renderer.reset();
      in.MeshInRenderer = nullptr;
      return false;
    }
    in.MeshInRenderer = mesh->GetDualMesh();
    in.MeshBuildTime = mesh->GetBuildTime();
    in.HasAccumulation = false;
    this->UploadTime.Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
vtkOverlappingAMR* vtkAMRDualMeshVolumeMapper::CheckInput()
{
  if (this->GetNumberOfInputConnections(0) < 1 || !this->GetInputDataObject(0, 0))
  {
    vtkErrorMacro("No input: call SetInputData(vtkOverlappingAMR*) or SetInputConnection().");
    return nullptr;
  }
  vtkDataObject* data = this->GetInputDataObject(0, 0);
  if (!vtkOverlappingAMR::SafeDownCast(data))
  {
    vtkErrorMacro("The input is a "
                  << data->GetClassName()
                  << "; vtkAMRDualMeshVolumeMapper renders vtkOverlappingAMR only "
                     "(use vtkSmartVolumeMapper for other data sets).");
    return nullptr;
  }
  vtkOverlappingAMR* amr = this->UpdateAndGetInput();
  if (!amr)
  {
    vtkErrorMacro("The input is not a vtkOverlappingAMR after its update.");
  }
  return amr;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateTransferFunction(vtkVolumeProperty* property)
{
  // Majorants follow the property's functions and unit distance.
  Internals& in = *this->Internal;
  const bool gray = property->GetColorChannels(0) == 1;
  vtkObject* color = gray ? static_cast<vtkObject*>(property->GetGrayTransferFunction(0))
                          : static_cast<vtkObject*>(property->GetRGBTransferFunction(0));
  vtkObject* opacity = property->GetScalarOpacity(0);
  const vtkMTimeType tfTime = std::max(color->GetMTime(), opacity->GetMTime());
  const bool stale = !in.HasTf || property != in.TfProperty || color != in.TfFunctions[0] ||
                     opacity != in.TfFunctions[1] ||
                     tfTime > this->TransferFunctionTime.GetMTime() ||
                     float(property->GetScalarOpacityUnitDistance(0)) != in.Tf.unitDistance;
  if (!stale)
  {
    return true;
  }
  amrdm::TransferFunction tf;
  std::string error, warning;
  if (!amrdm_vtk::MakeTransferFunction(property, tf, error, warning))
  {
    vtkErrorMacro("Bad volume property: " << error);
    return false;
  }
  if (!warning.empty() && warning != in.TfWarning)
  {
    vtkWarningMacro("Volume property: " << warning << ".");
  }
  in.TfWarning = warning;
  const bool same = in.HasTf && tf.lo == in.Tf.lo && tf.hi == in.Tf.hi &&
                    tf.logScale == in.Tf.logScale && tf.unitDistance == in.Tf.unitDistance &&
                    tf.table == in.Tf.table;
  if (!same)
  {
    in.Tf = tf;
    try
    {
      in.Renderer->setTransferFunction(in.Tf, this->NumberOfThreads);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro("Cannot set the transfer function on the " << this->GetDeviceAsString()
                                                               << " renderer: " << e.what());
      in.HasTf = false;
      return false;
    }
    in.HasAccumulation = false;
  }
  in.HasTf = true;
  in.TfProperty = property;
  in.TfFunctions[0] = color;
  in.TfFunctions[1] = opacity;
  this->TransferFunctionTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
amrdm::RenderParams vtkAMRDualMeshVolumeMapper::MakeRenderParams(
  vtkRenderer* ren, vtkVolume* vol, vtkOverlappingAMR* amr, int width, int height, bool& ok)
{
  ok = true;
  Internals& in = *this->Internal;
  vtkVolumeProperty* property = vol->GetProperty();
  if (!in.WarnedBlend && this->BlendMode != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    vtkWarningMacro("Only composite blending is supported; BlendMode is ignored.");
    in.WarnedBlend = true;
  }

  amrdm::RenderParams params;
  params.integrator = static_cast<amrdm::IntegratorType>(this->Integrator);
  params.maxBounces = this->MaximumBounces;
  params.rouletteStartBounce = std::min(params.rouletteStartBounce, this->MaximumBounces);
  params.anisotropy = float(this->Anisotropy);
  params.seed = static_cast<std::uint32_t>(this->Seed);
  params.stepSize = float(this->StepSize);
  if (!(this->StepSize > 0.0))
  {
    // Auto: half the finest cell, but at least 1/1000 of the AMR bounds' diagonal.
    double b[6];
    amr->GetBounds(b);
    const double diagonal =
      std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                (b[5] - b[4]) * (b[5] - b[4]));
    params.stepSize = float(amrdm::autoStepSize(in.Mesh->GetDualMesh()->finestSpacing, diagonal));
  }
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
  params.ambient = glm::vec3(this->Ambient[0], this->Ambient[1], this->Ambient[2]);
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
  if (model)
  {
    amrdm_vtk::LightsToDataFrame(model, sceneOrigin, params.lights, params.numLights);
  }
  params.width = width;
  params.height = height;
  params.threads = this->NumberOfThreads;
  return params;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::UpdateAccumulation(vtkRenderer* ren, vtkVolume* vol,
  const amrdm::RenderParams& params, const int viewport[4], bool& reset)
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
bool vtkAMRDualMeshVolumeMapper::AddSamples(amrdm::RenderParams params, bool reset)
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
    if (in.Renderer->renderPass(params, in.TMax.data(), in.TMin.data()))
    {
      in.Samples += params.samplesPerPass;
      // The cost per pixel sample sizes the next interactive frame.
      in.Interaction.RecordPass(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        double(params.width) * params.height * params.samplesPerPass);
    }
    in.Image = in.Renderer->image();
  }
  catch (const std::exception& e) // e.g. accumulation buffers larger than the free memory
  {
    vtkErrorMacro("Cannot render a " << params.width << " x " << params.height
                                     << " image: " << e.what());
    in.HasAccumulation = false;
    in.Image.clear();
    return false;
  }
  in.ImageSize[0] = params.width;
  in.ImageSize[1] = params.height;
  return true;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::RenderInteractiveFrame(
  vtkRenderer* ren, vtkVolume* vol, const amrdm::RenderParams& params, const int viewport[4])
{
  // One cheap frame (AMRDualMeshInteraction.h); the next still render restarts the accumulation.
  Internals& in = *this->Internal;
  in.HasAccumulation = false;
  in.Samples = 0;
  std::string error;
  if (!in.Interaction.RenderFrame(ren, *in.Renderer, in.Compositor, params, viewport,
        this->ClippingPlanes, vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix(),
        in.MeshInRenderer->sceneOrigin, this->InteractiveFrameTime,
        in.InteractiveReduction, error))
  {
    vtkErrorMacro("Cannot render an interactive frame: " << error);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& in = *this->Internal;
  ++in.RenderCount;
  in.LastRenderOk = false;

  // Derived products, each refreshed only when what it follows changed: the dual mesh (input,
  // array), the renderer and its upload (Device, mesh), the transfer function and majorants
  // (property), the accumulation (everything that makes the image).
  vtkOverlappingAMR* amr = this->CheckInput();
  if (!amr || !this->UpdateDualMesh(amr) || !this->UpdateRenderer())
  {
    return;
  }
  const auto start = std::chrono::steady_clock::now(); // the build is not part of the frame
  if (!this->UpdateTransferFunction(vol->GetProperty()))
  {
    return;
  }
  int viewport[4] = { 0, 0, 0, 0 }; // x0, y0, width, height
  ren->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  if (viewport[2] <= 0 || viewport[3] <= 0)
  {
    return;
  }
  bool ok = true;
  const amrdm::RenderParams params =
    this->MakeRenderParams(ren, vol, amr, viewport[2], viewport[3], ok);
  if (!ok)
  {
    return;
  }
  in.LastRenderInteractive = amrdm_vtk::InteractionPolicy::IsInteractive(
    ren->GetRenderWindow(), this->InteractiveUpdateRate);
  if (in.LastRenderInteractive)
  {
    in.LastRenderOk = this->RenderInteractiveFrame(ren, vol, params, viewport);
    this->LastRenderSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return;
  }
  bool reset = false;
  this->UpdateAccumulation(ren, vol, params, viewport, reset);
  if (!this->AddSamples(params, reset))
  {
    return;
  }
  // A tile of a large screenshot (vtkWindowToImageFilter / vtkRenderLargeImage scale, ParaView's
  // SaveScreenshot at another resolution) is rendered to the sample count the view had: each
  // tile is a new view, and a screenshot must not be noisier than the view it copies.
  const int* tileScale = ren->GetRenderWindow()->GetTileScale();
  if (tileScale[0] > 1 || tileScale[1] > 1)
  {
    while (in.Samples < in.ViewSamples)
    {
      const int before = in.Samples;
      if (!this->AddSamples(params, false))
      {
        return;
      }
      if (in.Samples == before)
      {
        break; // at MaximumSamples
      }
    }
  }
  else
  {
    // A resize alone (ParaView shrinks the view before it tiles a screenshot) keeps the count.
    const bool resized = viewport[2] != in.ViewSize[0] || viewport[3] != in.ViewSize[1];
    in.ViewSamples = reset && resized ? std::max(in.ViewSamples, in.Samples) : in.Samples;
    in.ViewSize[0] = viewport[2];
    in.ViewSize[1] = viewport[3];
  }
  if (in.Image.size() == std::size_t(4) * viewport[2] * viewport[3])
  {
    in.Compositor.Draw(ren, viewport[2], viewport[3], in.Image.data());
  }
  in.LastRenderOk = true;
  this->LastRenderSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshVolumeMapper::RenderUntil(vtkRenderWindow* window, int samples)
{
  Internals& in = *this->Internal;
  if (!window)
  {
    vtkErrorMacro("RenderUntil() needs a render window.");
    return in.Samples;
  }
  const int target = std::max(1, std::min(samples, this->MaximumSamples));
  in.SampleLimit = target;
  // Each render adds at least one sample unless the accumulation resets; cap the renders so a
  // scene that changes every frame cannot loop forever.
  for (int i = 0; i < 2 * target + 2 && in.Samples < target; ++i)
  {
    const int renders = in.RenderCount;
    window->Render();
    if (in.RenderCount == renders || !in.LastRenderOk)
    {
      break; // the volume was not rendered (not visible, or an error)
    }
  }
  in.SampleLimit = 0;
  return in.Samples;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Compositor.ReleaseGraphicsResources(window);
}

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

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* integrators[] = {
    "PATH_TRACER", "SINGLE_SCATTER", "RAY_MARCH", "DEBUG_PRIMITIVES", "DEBUG_COST"
  };
  os << indent << "Device: " << this->GetDeviceAsString()
     << (this->Internal->Renderer
            ? (this->Internal->Renderer->device() == amrdm::RenderDevice::Cuda ? " (rendering on CUDA)"
                                                                               : " (rendering on the CPU)")
            : "")
     << "\n";
  os << indent << "DeviceReport: " << this->Internal->DeviceReport << "\n";
  os << indent << "Integrator: " << this->Integrator << " (" << integrators[this->Integrator]
     << ")\n";
  os << indent << "ElementTest: "
     << (this->ElementTest == ELEMENT_TEST_BILINEAR ? "BILINEAR" : "PLANAR_FACES") << "\n";
  os << indent << "MaxNewtonIterations: " << this->MaxNewtonIterations << "\n";
  os << indent << "GridletSize: " << this->GridletSize << "\n";
  os << indent << "SamplesPerRender: " << this->SamplesPerRender << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "MaximumBounces: " << this->MaximumBounces << "\n";
  os << indent << "Anisotropy: " << this->Anisotropy << "\n";
  os << indent << "StepSize: " << this->StepSize << (this->StepSize > 0 ? "" : " (auto)") << "\n";
  os << indent << "SamplesPerCell: " << this->SamplesPerCell
     << (this->SamplesPerCell > 0 ? "" : " (off: uniform step)") << "\n";
  os << indent << "MajorantResolution: " << this->MajorantResolution
     << (this->MajorantResolution > 0 ? "" : " (auto)") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads
     << (this->NumberOfThreads > 0 ? "" : " (all cores)") << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Ambient: (" << this->Ambient[0] << ", " << this->Ambient[1] << ", "
     << this->Ambient[2] << ")\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveFrameTime: " << this->InteractiveFrameTime
     << (this->InteractiveFrameTime > 0 ? "" : " (full resolution)") << "\n";
  os << indent << "LastRenderInteractive: " << this->Internal->LastRenderInteractive
     << " (reduction " << this->Internal->InteractiveReduction << ")\n";
  os << indent << "NumberOfSamples: " << this->Internal->Samples << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  os << indent << "UploadTime: " << this->UploadTime.GetMTime() << "\n";
  os << indent << "TransferFunctionTime: " << this->TransferFunctionTime.GetMTime() << "\n";
  os << indent << "AccumulationTime: " << this->AccumulationTime.GetMTime() << "\n";
  os << indent << "DualMesh:\n";
  this->Internal->Mesh->PrintSelf(os, indent.GetNextIndent());
}
