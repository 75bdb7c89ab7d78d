// vtkAMRDualMeshVolumeMapper: the derived products that live in the renderer: the renderer for
// Device (from the compiled factory), its copy of the dual mesh (UploadTime) and the transfer
// function with its majorants (TransferFunctionTime).
#include "vtkAMRDualMeshVolumeMapperInternals.h"

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateRenderer()
{
  Internals& in = *this->Internal;
  if (!in.Renderer || in.RendererDevice != this->Device)
  {
    in.Renderer.reset();
    in.MeshInRenderer = nullptr;
    in.ProxyInRenderer = nullptr;
    in.ProxyAccepted = false;
    in.HasTf = false;
    in.Accum.Invalidate();
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
        vtkErrorMacro(
          "Device " << this->GetDeviceAsString() << ": " << error << " (use Device AUTO or CPU).");
        in.DeviceError = error;
      }
      return false;
    }
    in.RendererDevice = this->Device;
  }
  // The proxy the renderer should hold (none without a region); dropped first when it changes,
  // so that the renderer never holds a mesh that was rebuilt.
  const amrdm::DualMesh* proxy = in.ProxyInput && in.Region.Active() && in.ProxyMesh->GetDualMesh()
                                   ? in.ProxyMesh->GetDualMesh()
                                   : nullptr;
  bool proxyStale =
    proxy != in.ProxyInRenderer || (proxy && in.ProxyMesh->GetBuildTime() != in.ProxyBuildTime);
  for (int i = 0; i < 6 && proxy && !proxyStale; ++i)
  {
    proxyStale = in.ProxyBox[i] != in.Region.Bounds[i];
  }
  if (proxyStale && in.ProxyInRenderer)
  {
    if (in.ProxyAccepted)
    {
      in.Renderer->setProxy(nullptr, glm::vec3(0.0f), glm::vec3(0.0f));
      in.Accum.Invalidate();
    }
    in.ProxyInRenderer = nullptr;
    in.ProxyAccepted = false;
  }
  vtkAMRDualMesh* mesh = in.Mesh;
  if (mesh->GetDualMesh() != in.MeshInRenderer || mesh->GetBuildTime() != in.MeshBuildTime)
  {
    proxyStale = proxyStale || proxy;
    const int r = this->MajorantResolution;
    try
    {
      in.Renderer->setMesh(mesh->GetDualMesh(), glm::ivec3(r), this->GetEffectiveNumberOfThreads());
    }
    catch (const std::exception& e) // e.g. a device out of memory with Device CUDA
    {
      vtkErrorMacro("Cannot upload the dual mesh to the " << this->GetDeviceAsString()
                                                          << " renderer: " << e.what());
      in.Renderer.reset();
      in.MeshInRenderer = nullptr;
      in.ProxyInRenderer = nullptr;
      in.ProxyAccepted = false;
      return false;
    }
    in.MeshInRenderer = mesh->GetDualMesh();
    in.MeshBuildTime = mesh->GetBuildTime();
    in.Accum.Invalidate();
    this->UploadTime.Modified();
  }
  if (proxyStale && proxy)
  {
    const glm::dvec3 origin = mesh->GetDualMesh()->sceneOrigin; // the proxy shares it
    glm::vec3 lo, hi;
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = float(in.Region.Bounds[2 * d] - origin[d]);
      hi[d] = float(in.Region.Bounds[2 * d + 1] - origin[d]);
    }
    // Tried once per proxy, region and renderer: a refusal is said once and not retried.
    in.ProxyInRenderer = proxy;
    in.ProxyBuildTime = in.ProxyMesh->GetBuildTime();
    std::copy(in.Region.Bounds, in.Region.Bounds + 6, in.ProxyBox);
    try
    {
      in.Renderer->setProxy(proxy, lo, hi, this->GetEffectiveNumberOfThreads());
      in.ProxyAccepted = true;
      in.ProxyError.clear();
    }
    catch (const std::exception& e) // e.g. the CUDA renderer
    {
      if (e.what() != in.ProxyError)
      {
        vtkErrorMacro("Cannot use the region's proxy on the " << this->GetDeviceAsString()
                                                              << " renderer: " << e.what()
                                                              << "; drawing without it.");
        in.ProxyError = e.what();
      }
    }
    in.Accum.Invalidate();
  }
  return true;
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
      in.Renderer->setTransferFunction(in.Tf, this->GetEffectiveNumberOfThreads());
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro("Cannot set the transfer function on the " << this->GetDeviceAsString()
                                                               << " renderer: " << e.what());
      in.HasTf = false;
      return false;
    }
    in.Accum.Invalidate();
  }
  in.HasTf = true;
  in.TfProperty = property;
  in.TfFunctions[0] = color;
  in.TfFunctions[1] = opacity;
  this->TransferFunctionTime.Modified();
  return true;
}

vtkTypeUInt64 vtkAMRDualMeshVolumeMapper::GetAccelerationBytes()
{
  const Internals& in = *this->Internal;
  return in.Renderer ? in.Renderer->accelerationBytes() : 0;
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
