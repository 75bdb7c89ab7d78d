// vtkAMRDualMeshVolumeMapper: its API, Render() in steps (input slot, renderer slot, frame, still
// or interactive pass; docs/MAPPER.md) and PrintSelf.
#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshDepthPeeling.h"
#include "vtkAMRDualMeshVolumeMapperInternals.h"

vtkStandardNewMacro(vtkAMRDualMeshVolumeMapper);

//------------------------------------------------------------------------------
vtkAMRDualMeshVolumeMapper::vtkAMRDualMeshVolumeMapper()
  : Internal(new Internals(this))
{
}

vtkAMRDualMeshVolumeMapper::~vtkAMRDualMeshVolumeMapper() = default;

const char* vtkAMRDualMeshVolumeMapper::GetDeviceAsString()
{
  static const char* const names[] = { "AUTO", "CPU", "CUDA" }; // Device is clamped to them
  return names[this->Device];
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
  return this->Internal->Input.GetMesh();
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
double* vtkAMRDualMeshVolumeMapper::GetBounds()
{
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    // vtkVolume skips Render() without input, so the renderer's bounds query reports it.
    vtkErrorMacro("No input: call SetInputData(vtkOverlappingAMR*) or SetInputConnection().");
  }
  this->Internal->Input.GetBounds(this->Internal->Region, this->Bounds);
  return this->Bounds;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::SetRegion(int index,
  const double regionBounds[6],
  const double domainBounds[6])
{
  if (this->Internal->Region.Set(index, regionBounds, domainBounds))
  {
    this->Modified();
  }
}

void vtkAMRDualMeshVolumeMapper::ClearRegion()
{
  if (this->Internal->Region.Clear())
  {
    this->Modified();
  }
}

int vtkAMRDualMeshVolumeMapper::GetRegionIndex()
{
  return this->Internal->Region.Index;
}

void vtkAMRDualMeshVolumeMapper::SetRegionProxy(vtkOverlappingAMR* proxy)
{
  if (this->Internal->Input.SetProxy(proxy))
  {
    this->Modified();
  }
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
  bool meshLost = false;
  vtkOverlappingAMR* amr = in.Input.CheckInput();
  if (!amr || !in.Input.Update(amr, in.Region, meshLost))
  {
    if (meshLost)
    {
      in.Slot.ForgetMesh();
    }
    return;
  }
  in.LastRenderOk =
    in.Slot.Update(this, in.Input, in.Region, vol->GetProperty()) && in.Frames.Render(ren, vol);
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshVolumeMapper::GetEffectiveNumberOfThreads() const
{
  return vtkAMRDualMesh::ResolveNumberOfThreads(this->NumberOfThreads);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkAMRDualMeshVolumeMapper::GetAccumulationKey(vtkRenderer* ren, vtkVolume* vol)
{
  if (!ren || !vol || !vol->GetProperty())
  {
    return 0;
  }
  amrdm_vtk::AccumulationKey key;
  this->Internal->Frames.MakeClientKey(ren, vol, this->Internal->Region, key);
  return this->Internal->Accum.ClientKey(key);
}

//------------------------------------------------------------------------------
vtkTypeUInt64 vtkAMRDualMeshVolumeMapper::GetAccelerationBytes()
{
  return this->Internal->Slot.GetAccelerationBytes();
}

int vtkAMRDualMeshVolumeMapper::GetRenderingDevice()
{
  return this->Internal->Slot.GetRenderingDevice();
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::WriteLastImageEXR(const char* fileName)
{
  std::string error;
  if (!this->Internal->Accum.WriteEXR(fileName, error))
  {
    vtkErrorMacro("WriteLastImageEXR(): " << error);
    return false;
  }
  return true;
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
  const int device = this->Internal->Slot.GetRenderingDevice();
  os << indent << "RenderingDevice: "
     << (device < 0               ? "none yet"
          : device == DEVICE_CUDA ? "CUDA"
                                  : "CPU")
     << " (Device " << this->GetDeviceAsString() << ")\n";
  os << indent << "DeviceReport: " << this->Internal->Slot.GetDeviceReport() << "\n";
  // BEGIN GENERATED mapper-print (Tools/generate_parameters.py)
  // clang-format off
  os << indent << "Integrator: " << this->Integrator << "\n";
  os << indent << "Device: " << this->Device << "\n";
  os << indent << "SamplesPerRender: " << this->SamplesPerRender << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "ScatteringAnisotropy: " << this->ScatteringAnisotropy << "\n";
  os << indent << "EnvironmentRadiance: (" << this->EnvironmentRadiance[0] << ", " << this->EnvironmentRadiance[1] << ", "
     << this->EnvironmentRadiance[2] << ")\n";
  os << indent << "EmbedIsosurfaces: " << this->EmbedIsosurfaces << "\n";
  os << indent << "MaximumBounces: " << this->MaximumBounces << "\n";
  os << indent << "StepSize: " << this->StepSize << "\n";
  os << indent << "SamplesPerCell: " << this->SamplesPerCell << "\n";
  os << indent << "ElementTest: " << this->ElementTest << "\n";
  os << indent << "MaxNewtonIterations: " << this->MaxNewtonIterations << "\n";
  os << indent << "GridletSize: " << this->GridletSize << "\n";
  os << indent << "BVHLeafSize: " << this->BVHLeafSize << "\n";
  os << indent << "MajorantResolution: " << this->MajorantResolution << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "InteractiveFrameTime: " << this->InteractiveFrameTime << "\n";
  os << indent << "FinalRenderTime: " << this->FinalRenderTime << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  // clang-format on
  // END GENERATED mapper-print
  os << indent << "IntegratorName: " << amrdm::kIntegrators[this->Integrator].vtkName << "\n";
  os << indent << "EffectiveNumberOfThreads: " << this->GetEffectiveNumberOfThreads() << "\n";
  os << indent << "LastRenderAborted: " << this->Internal->LastRenderAborted << "\n";
  os << indent << "LastRenderInteractive: " << this->Internal->LastRenderInteractive
     << " (reduction " << this->Internal->InteractiveReduction << ")\n";
  os << indent << "NumberOfSamples: " << this->Internal->Accum.Samples << "\n";
  os << indent << "LastRenderSeconds: " << this->LastRenderSeconds << "\n";
  this->Internal->Input.PrintRegion(
    os, indent, this->Internal->Region, this->Internal->Slot.GetProxyAccepted());
  os << indent << "UploadTime: " << this->Internal->Slot.UploadTime.GetMTime() << "\n";
  os << indent << "TransferFunctionTime: " << this->Internal->Slot.TransferFunctionTime.GetMTime()
     << "\n";
  os << indent << "AccumulationTime: " << this->Internal->Accum.GetTime() << "\n";
  os << indent << "DualMesh:\n";
  this->Internal->Input.GetMesh()->PrintSelf(os, indent.GetNextIndent());
}
