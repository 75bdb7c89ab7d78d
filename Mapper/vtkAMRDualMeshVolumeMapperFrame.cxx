// vtkAMRDualMeshVolumeMapper: one frame, in the order Render() takes its steps: the renderer
// slot brought up to date (AMRDualMeshRendererSlot), the frame's kernel parameters
// (AMRDualMeshFrameBuilder), then a still frame (the accumulation's reset key, a pass, the
// screenshot-tile rule, the composite: AMRDualMeshAccumulation) or a cheap interactive frame;
// and what reads the slot and the accumulation back (devices, bytes, the EXR image, the key).
#include "vtkAMRDualMeshVolumeMapperInternals.h"

//------------------------------------------------------------------------------
int vtkAMRDualMeshVolumeMapper::GetEffectiveNumberOfThreads() const
{
  return vtkAMRDualMesh::ResolveNumberOfThreads(this->NumberOfThreads);
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateRendererSlot(vtkVolumeProperty* property)
{
  Internals& in = *this->Internal;
  AMRDualMeshRendererSlot::Settings settings;
  settings.Device = this->Device;
  settings.DeviceName = this->GetDeviceAsString();
  settings.MajorantResolution = this->MajorantResolution;
  settings.Threads = this->GetEffectiveNumberOfThreads();
  // The proxy the renderer should hold: none without a region.
  const amrdm::DualMesh* proxy = in.ProxyInput && in.Region.Active() && in.ProxyMesh->GetDualMesh()
                                   ? in.ProxyMesh->GetDualMesh()
                                   : nullptr;
  return in.Slot.UpdateRenderer(settings, in.Mesh, in.ProxyMesh, proxy, in.Region) &&
         in.Slot.UpdateTransferFunction(settings, property);
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::UpdateFrame(vtkRenderer* ren,
  vtkVolume* vol,
  const int viewport[4],
  amrdm::RenderParams& params)
{
  Internals& in = *this->Internal;
  const glm::dvec3 o = in.Slot.GetMesh()->sceneOrigin; // the scene frame
  const double origin[3] = { o.x, o.y, o.z };
  return in.Frames.MakeParams(ren, vol, in.Region, origin, viewport[2], viewport[3], true, params);
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::RenderStillFrame(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm::RenderParams& params,
  const int viewport[4])
{
  Internals& in = *this->Internal;
  amrdm::Renderer& renderer = *in.Slot.GetRenderer();
  amrdm_vtk::AccumulationKey key;
  in.Frames.MakeKey(
    ren, vol, in.Compositor, *in.Slot.GetMesh(), params, viewport, in.Slot.GetChangeTime(), key);
  const bool reset = in.Accum.Update(key, renderer);
  const int limit =
    in.SampleLimit > 0 ? std::min(this->MaximumSamples, in.SampleLimit) : this->MaximumSamples;
  const int* tileScale = ren->GetRenderWindow()->GetTileScale();
  std::string error;
  if (!in.Accum.AddSamples(renderer,
        params,
        reset,
        limit,
        this->SamplesPerRender,
        ren->GetRenderWindow(),
        in.Interaction,
        in.LastRenderAborted,
        error) ||
      !in.Accum.MatchView(renderer,
        params,
        reset,
        tileScale[0] > 1 || tileScale[1] > 1,
        limit,
        this->SamplesPerRender,
        in.Interaction,
        in.LastRenderAborted,
        error))
  {
    vtkErrorMacro(
      "Cannot render a " << params.width << " x " << params.height << " image: " << error);
    return false;
  }
  const std::vector<float>& image = in.Accum.GetImage();
  if (image.size() == std::size_t(4) * viewport[2] * viewport[3])
  {
    in.Compositor.Draw(ren, viewport[2], viewport[3], image.data());
  }
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
        *in.Slot.GetRenderer(),
        in.Compositor,
        params,
        viewport,
        this->ClippingPlanes,
        vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix(),
        in.Slot.GetMesh()->sceneOrigin,
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
  const amrdm::Renderer* renderer = this->Internal->Slot.GetRenderer();
  return renderer ? renderer->accelerationBytes() : 0;
}

int vtkAMRDualMeshVolumeMapper::GetRenderingDevice()
{
  const amrdm::Renderer* renderer = this->Internal->Slot.GetRenderer();
  if (!renderer)
  {
    return -1;
  }
  return renderer->device() == amrdm::RenderDevice::Cuda ? DEVICE_CUDA : DEVICE_CPU;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshVolumeMapper::WriteLastImageEXR(const char* fileName)
{
  const Internals& in = *this->Internal;
  if (!fileName || in.Accum.GetImage().empty())
  {
    vtkErrorMacro("WriteLastImageEXR(): " << (fileName ? "nothing rendered yet" : "no file name"));
    return false;
  }
  std::string error;
  if (!amrdm_vtk::WriteEXR(fileName,
        in.Accum.GetImageSize()[0],
        in.Accum.GetImageSize()[1],
        in.Accum.GetImage().data(),
        error))
  {
    vtkErrorMacro("WriteLastImageEXR(): " << error);
    return false;
  }
  return true;
}
