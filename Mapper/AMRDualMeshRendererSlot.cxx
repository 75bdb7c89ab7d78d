#include "AMRDualMeshRendererSlot.h"

#include "AMRDualMeshInputSlot.h"
#include "AMRDualMeshRegion.h"
#include "AMRDualMeshSceneConversion.h"
#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkColorTransferFunction.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include "mesh/DualMesh.h"
#include "render/RendererFactory.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <set>

//------------------------------------------------------------------------------
bool AMRDualMeshRendererSlot::UpdateRenderer(const Settings& settings,
  vtkAMRDualMesh* mesh,
  vtkAMRDualMesh* proxyMesh,
  const amrdm::DualMesh* proxy,
  const amrdm_vtk::RegionClip& region)
{
  if (!this->Renderer || this->RendererDevice != settings.Device)
  {
    this->Renderer.reset();
    this->MeshInRenderer = nullptr;
    this->ProxyInRenderer = nullptr;
    this->ProxyAccepted = false;
    this->HasTf = false;
    this->ChangeTime.Modified();
    try
    {
      // The factory's line (which device and why; a fallback) goes to DeviceReport and, once per
      // process and text, to the output window as plain text: not a warning, so that a
      // ParaView view does not pop up a dialog for the expected CPU choice.
      this->DeviceReport.clear();
      std::string& report = this->DeviceReport;
      this->Renderer = amrdm::createRenderer(static_cast<amrdm::RenderDevice>(settings.Device),
        [&report](const std::string& line)
        {
          report = line;
          static std::mutex mutex;
          static std::set<std::string> said;
          std::lock_guard<std::mutex> lock(mutex);
          if (said.insert(line).second)
          {
            vtkOutputWindowDisplayText(("vtkAMRDualMeshVolumeMapper: " + line + "\n").c_str());
          }
        });
      this->DeviceError.clear();
    }
    catch (const std::exception& e)
    {
      const std::string error = e.what();
      if (error != this->DeviceError)
      {
        vtkErrorWithObjectMacro(this->Owner,
          "Device " << settings.DeviceName << ": " << error << " (use Device AUTO or CPU).");
        this->DeviceError = error;
      }
      return false;
    }
    this->RendererDevice = settings.Device;
  }
  // The proxy the renderer should hold (none without a region); dropped first when it changes,
  // so that the renderer never holds a mesh that was rebuilt.
  bool proxyStale =
    proxy != this->ProxyInRenderer || (proxy && proxyMesh->GetBuildTime() != this->ProxyBuildTime);
  for (int i = 0; i < 6 && proxy && !proxyStale; ++i)
  {
    proxyStale = this->ProxyBox[i] != region.Bounds[i];
  }
  if (proxyStale && this->ProxyInRenderer)
  {
    if (this->ProxyAccepted)
    {
      this->Renderer->setProxy(nullptr, glm::vec3(0.0f), glm::vec3(0.0f));
      this->ChangeTime.Modified();
    }
    this->ProxyInRenderer = nullptr;
    this->ProxyAccepted = false;
  }
  if (mesh->GetDualMesh() != this->MeshInRenderer || mesh->GetBuildTime() != this->MeshBuildTime)
  {
    proxyStale = proxyStale || proxy;
    const int r = settings.MajorantResolution;
    try
    {
      this->Renderer->setMesh(mesh->GetDualMesh(), glm::ivec3(r), settings.Threads);
    }
    catch (const std::exception& e) // e.g. a device out of memory with Device CUDA
    {
      vtkErrorWithObjectMacro(this->Owner,
        "Cannot upload the dual mesh to the " << settings.DeviceName << " renderer: " << e.what());
      this->Renderer.reset();
      this->MeshInRenderer = nullptr;
      this->ProxyInRenderer = nullptr;
      this->ProxyAccepted = false;
      return false;
    }
    this->MeshInRenderer = mesh->GetDualMesh();
    this->MeshBuildTime = mesh->GetBuildTime();
    this->UploadTime.Modified();
    this->ChangeTime.Modified();
  }
  if (proxyStale && proxy)
  {
    const glm::dvec3 origin = mesh->GetDualMesh()->sceneOrigin; // the proxy shares it
    glm::vec3 lo, hi;
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = float(region.Bounds[2 * d] - origin[d]);
      hi[d] = float(region.Bounds[2 * d + 1] - origin[d]);
    }
    // Tried once per proxy, region and renderer: a refusal is said once and not retried.
    this->ProxyInRenderer = proxy;
    this->ProxyBuildTime = proxyMesh->GetBuildTime();
    std::copy(region.Bounds, region.Bounds + 6, this->ProxyBox);
    try
    {
      this->Renderer->setProxy(proxy, lo, hi, settings.Threads);
      this->ProxyAccepted = true;
      this->ProxyError.clear();
    }
    catch (const std::exception& e) // e.g. the CUDA renderer
    {
      if (e.what() != this->ProxyError)
      {
        vtkErrorWithObjectMacro(this->Owner,
          "Cannot use the region's proxy on the "
            << settings.DeviceName << " renderer: " << e.what() << "; drawing without it.");
        this->ProxyError = e.what();
      }
    }
    this->ChangeTime.Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
bool AMRDualMeshRendererSlot::UpdateTransferFunction(const Settings& settings,
  vtkVolumeProperty* property)
{
  // Majorants follow the property's functions and unit distance.
  const bool gray = property->GetColorChannels(0) == 1;
  vtkObject* color = gray ? static_cast<vtkObject*>(property->GetGrayTransferFunction(0))
                          : static_cast<vtkObject*>(property->GetRGBTransferFunction(0));
  vtkObject* opacity = property->GetScalarOpacity(0);
  const vtkMTimeType tfTime = std::max(color->GetMTime(), opacity->GetMTime());
  const bool stale = !this->HasTf || property != this->TfProperty ||
                     color != this->TfFunctions[0] || opacity != this->TfFunctions[1] ||
                     tfTime > this->TransferFunctionTime.GetMTime() ||
                     float(property->GetScalarOpacityUnitDistance(0)) != this->Tf.unitDistance;
  if (!stale)
  {
    return true;
  }
  amrdm::TransferFunction tf;
  std::string error, warning;
  if (!amrdm_vtk::MakeTransferFunction(property, tf, error, warning))
  {
    vtkErrorWithObjectMacro(this->Owner, "Bad volume property: " << error);
    return false;
  }
  if (!warning.empty() && warning != this->TfWarning)
  {
    vtkWarningWithObjectMacro(this->Owner, "Volume property: " << warning << ".");
  }
  this->TfWarning = warning;
  const bool same = this->HasTf && tf.lo == this->Tf.lo && tf.hi == this->Tf.hi &&
                    tf.logScale == this->Tf.logScale && tf.unitDistance == this->Tf.unitDistance &&
                    tf.table == this->Tf.table;
  if (!same)
  {
    this->Tf = tf;
    try
    {
      this->Renderer->setTransferFunction(this->Tf, settings.Threads);
    }
    catch (const std::exception& e)
    {
      vtkErrorWithObjectMacro(this->Owner,
        "Cannot set the transfer function on the " << settings.DeviceName
                                                   << " renderer: " << e.what());
      this->HasTf = false;
      return false;
    }
    this->ChangeTime.Modified();
  }
  this->HasTf = true;
  this->TfProperty = property;
  this->TfFunctions[0] = color;
  this->TfFunctions[1] = opacity;
  this->TransferFunctionTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool AMRDualMeshRendererSlot::Update(vtkAMRDualMeshVolumeMapper* mapper,
  const AMRDualMeshInputSlot& input,
  const amrdm_vtk::RegionClip& region,
  vtkVolumeProperty* property)
{
  Settings settings;
  settings.Device = mapper->GetDevice();
  settings.DeviceName = mapper->GetDeviceAsString();
  settings.MajorantResolution = mapper->GetMajorantResolution();
  settings.Threads = mapper->GetEffectiveNumberOfThreads();
  return this->UpdateRenderer(settings,
           input.GetMesh(),
           input.GetProxyMesh(),
           input.GetProxyToRender(region),
           region) &&
         this->UpdateTransferFunction(settings, property);
}

int AMRDualMeshRendererSlot::GetRenderingDevice() const
{
  if (!this->Renderer)
  {
    return -1;
  }
  return this->Renderer->device() == amrdm::RenderDevice::Cuda
           ? vtkAMRDualMeshVolumeMapper::DEVICE_CUDA
           : vtkAMRDualMeshVolumeMapper::DEVICE_CPU;
}

vtkTypeUInt64 AMRDualMeshRendererSlot::GetAccelerationBytes() const
{
  return this->Renderer ? this->Renderer->accelerationBytes() : 0;
}
