#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshCompositor.h"
#include "AMRDualMeshDepthPeeling.h"
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
#include "vtkOpenGLRenderPass.h"
#include "vtkOutputWindow.h"
#include "vtkOverlappingAMR.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUniformGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "mesh/DualMesh.h"
#include "render/RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "vtkAMRDualMeshVolumeMapperInternals.h"

vtkStandardNewMacro(vtkAMRDualMeshVolumeMapper);

//------------------------------------------------------------------------------
vtkAMRDualMeshVolumeMapper::vtkAMRDualMeshVolumeMapper()
  : Internal(new Internals(this))
{
  Internals& in = *this->Internal;
  in.ProgressForwarder->SetCallback(&Internals::ForwardProgress);
  in.ProgressForwarder->SetClientData(this);
  in.Mesh->AddObserver(vtkCommand::ProgressEvent, in.ProgressForwarder);
  in.ErrorCatcher->SetCallback(&Internals::CatchError);
  in.ErrorCatcher->SetClientData(&in);
  in.Mesh->AddObserver(vtkCommand::ErrorEvent, in.ErrorCatcher);
  in.ProxyMesh->AddObserver(vtkCommand::ErrorEvent, in.ErrorCatcher);
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
  return this->Internal->Slot.GetDeviceReport().c_str();
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
  return this->Internal->Accum.Samples;
}

bool vtkAMRDualMeshVolumeMapper::GetLastRenderInteractive()
{
  return this->Internal->LastRenderInteractive;
}

//------------------------------------------------------------------------------
// The mapper's constants are the rows of the kernels' integrator list.
static_assert(
  vtkAMRDualMeshVolumeMapper::PATH_TRACER == int(amrdm::IntegratorType::PathTracer) &&
    vtkAMRDualMeshVolumeMapper::SINGLE_SCATTER == int(amrdm::IntegratorType::SingleScatter) &&
    vtkAMRDualMeshVolumeMapper::RAY_MARCH == int(amrdm::IntegratorType::RayMarch) &&
    vtkAMRDualMeshVolumeMapper::DEBUG_PRIMITIVES == int(amrdm::IntegratorType::DebugPrimitive) &&
    vtkAMRDualMeshVolumeMapper::DEBUG_COST == int(amrdm::IntegratorType::DebugCost),
  "vtkAMRDualMeshVolumeMapper::Integrators differ from render/IntegratorList.h");

void vtkAMRDualMeshVolumeMapper::SetIntegrator(int integrator)
{
  // Clamped like every ranged setter (vtkSetClampMacro), with a warning naming the range.
  const int clamped = std::min(std::max(integrator, 0), amrdm::kIntegratorCount - 1);
  if (clamped != integrator)
  {
    vtkWarningMacro("SetIntegrator("
                    << integrator << "): expected 0.." << amrdm::kIntegratorCount - 1
                    << " (PATH_TRACER, SINGLE_SCATTER, RAY_MARCH, ...); using " << clamped << " ("
                    << amrdm::kIntegrators[clamped].name << ")");
  }
  if (this->Integrator != clamped)
  {
    this->Integrator = clamped;
    this->Modified();
  }
}

const char* vtkAMRDualMeshVolumeMapper::GetIntegratorAsString()
{
  return amrdm::kIntegrators[this->Integrator].name;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::GetLastRenderAborted()
{
  return this->Internal->LastRenderAborted;
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
  else if (this->Internal->Region.Active())
  {
    std::copy(this->Internal->Region.Bounds, this->Internal->Region.Bounds + 6, this->Bounds);
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
  // The array and its association (point data: the vertex-centred field), chosen the VTK way.
  std::string array, message;
  int association = 0;
  switch (amrdm_vtk::SelectArray(amr,
    this->ScalarMode,
    this->ArrayAccessMode,
    this->ArrayId,
    this->ArrayName,
    array,
    association,
    message))
  {
    case amrdm_vtk::ArraySelection::Missing:
      vtkErrorMacro(<< message);
      return false;
    case amrdm_vtk::ArraySelection::Chosen:
      break;
  }
  in.InputError.clear();
  in.Mesh->SetArrayAssociation(association);
  if (!this->BuildDualMesh(in.Mesh, amr, array))
  {
    vtkErrorMacro("Cannot build the dual mesh of '" << array << "': " << in.MeshError);
    in.Slot.ForgetMesh();
    return false;
  }
  this->UpdateRegionProxy(array);
  return true;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::BuildDualMesh(vtkAMRDualMesh* mesh,
  vtkOverlappingAMR* amr,
  const std::string& array)
{
  if (mesh->GetInputData() != amr)
  {
    mesh->SetInputData(amr);
  }
  if (!mesh->GetArrayName() || array != mesh->GetArrayName())
  {
    mesh->SetArrayName(array.c_str());
  }
  mesh->SetArrayAssociation(this->Internal->Mesh->GetArrayAssociation()); // the proxy's too
  mesh->SetGridletSize(this->GridletSize);
  mesh->SetBVHLeafSize(this->BVHLeafSize);
  mesh->SetNumberOfThreads(this->NumberOfThreads);
  this->Internal->MeshError.clear();
  return mesh->Update();
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
void vtkAMRDualMeshVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& in = *this->Internal;
  ++in.RenderCount;
  in.LastRenderOk = false;
  in.LastRenderAborted = false;

  if (!amrdm_vtk::DrawOutsideDepthPeeling(ren, vol))
  {
    in.LastRenderOk = true; // the next render draws the volume
    return;
  }

  // Derived products, each refreshed only when what it follows changed: the dual mesh (input,
  // array), the renderer slot (Device, mesh, proxy, transfer function and majorants), the frame
  // (VTK's view -> kernel parameters) and the accumulation (its reset key).
  vtkOverlappingAMR* amr = this->CheckInput();
  if (!amr || !this->UpdateDualMesh(amr) || !this->UpdateRendererSlot(vol->GetProperty()))
  {
    return;
  }
  // Neither the build nor the transfer-function setup (majorants, culling) is part of the frame.
  const auto start = std::chrono::steady_clock::now();
  int viewport[4] = { 0, 0, 0, 0 }; // x0, y0, width, height
  ren->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  amrdm::RenderParams params;
  if (viewport[2] <= 0 || viewport[3] <= 0 || !this->UpdateFrame(ren, vol, viewport, params))
  {
    return;
  }
  in.LastRenderInteractive = amrdm_vtk::InteractionPolicy::IsInteractive(
    ren->GetRenderWindow(), this->InteractiveUpdateRate);
  in.LastRenderOk = in.LastRenderInteractive
                      ? this->RenderInteractiveFrame(ren, vol, params, viewport)
                      : this->RenderStillFrame(ren, vol, params, viewport);
  if (in.LastRenderOk || in.LastRenderInteractive)
  {
    this->LastRenderSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshVolumeMapper::RenderUntil(vtkRenderWindow* window, int samples)
{
  Internals& in = *this->Internal;
  if (!window)
  {
    vtkErrorMacro("RenderUntil() needs a render window.");
    return in.Accum.Samples;
  }
  const int target = std::max(1, std::min(samples, this->MaximumSamples));
  in.SampleLimit = target;
  // Each render adds at least one sample unless the accumulation resets; cap the renders so a
  // scene that changes every frame cannot loop forever.
  for (int i = 0; i < 2 * target + 2 && in.Accum.Samples < target; ++i)
  {
    const int renders = in.RenderCount;
    window->Render();
    if (in.RenderCount == renders || !in.LastRenderOk)
    {
      break; // the volume was not rendered (not visible, or an error)
    }
  }
  in.SampleLimit = 0;
  return in.Accum.Samples;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internal->Compositor.ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Device: " << this->GetDeviceAsString()
     << (this->Internal->Slot.GetRenderer()
            ? (this->Internal->Slot.GetRenderer()->device() == amrdm::RenderDevice::Cuda
                  ? " (rendering on CUDA)"
                  : " (rendering on the CPU)")
            : "")
     << "\n";
  os << indent << "DeviceReport: " << this->Internal->Slot.GetDeviceReport() << "\n";
  os << indent << "Integrator: " << this->Integrator << " ("
     << amrdm::kIntegrators[this->Integrator].vtkName << ")\n";
  os << indent << "ElementTest: "
     << (this->ElementTest == ELEMENT_TEST_BILINEAR ? "BILINEAR" : "PLANAR_FACES") << "\n";
  os << indent << "MaxNewtonIterations: " << this->MaxNewtonIterations << "\n";
  os << indent << "GridletSize: " << this->GridletSize << "\n";
  os << indent << "BVHLeafSize: " << this->BVHLeafSize << "\n";
  os << indent << "SamplesPerRender: " << this->SamplesPerRender << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "MaximumBounces: " << this->MaximumBounces << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "StepSize: " << this->StepSize << (this->StepSize > 0 ? "" : " (auto)") << "\n";
  os << indent << "SamplesPerCell: " << this->SamplesPerCell
     << (this->SamplesPerCell > 0 ? "" : " (off: uniform step)") << "\n";
  os << indent << "MajorantResolution: " << this->MajorantResolution
     << (this->MajorantResolution > 0 ? "" : " (auto)") << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << " (uses "
     << this->GetEffectiveNumberOfThreads() << ")\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "EnvironmentRadiance: (" << this->EnvironmentRadiance[0] << ", "
     << this->EnvironmentRadiance[1] << ", " << this->EnvironmentRadiance[2] << ")\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveFrameTime: " << this->InteractiveFrameTime
     << (this->InteractiveFrameTime > 0 ? "" : " (full resolution)") << "\n";
  os << indent << "LastRenderAborted: " << this->Internal->LastRenderAborted << "\n";
  os << indent << "LastRenderInteractive: " << this->Internal->LastRenderInteractive
     << " (reduction " << this->Internal->InteractiveReduction << ")\n";
  os << indent << "NumberOfSamples: " << this->Internal->Accum.Samples << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  this->PrintRegion(os, indent);
  os << indent << "UploadTime: " << this->Internal->Slot.UploadTime.GetMTime() << "\n";
  os << indent << "TransferFunctionTime: " << this->Internal->Slot.TransferFunctionTime.GetMTime()
     << "\n";
  os << indent << "AccumulationTime: " << this->Internal->Accum.GetTime() << "\n";
  os << indent << "DualMesh:\n";
  this->Internal->Mesh->PrintSelf(os, indent.GetNextIndent());
}
