// AMRDualMeshFrameBuilder: one frame of the mapper, once its input and renderer slots are up to
// date: the kernel parameters of the tiled viewport, then a still frame (the accumulation's reset
// key, a pass, the screenshot-tile rule, the composite: AMRDualMeshAccumulation) or a cheap
// interactive frame (AMRDualMeshInteraction). Reads and writes the mapper's state (a friend).
#include "vtkAMRDualMeshVolumeMapperInternals.h"

#include "AMRDualMeshSurfaceDepth.h"

//------------------------------------------------------------------------------
bool AMRDualMeshFrameBuilder::Render(vtkRenderer* ren, vtkVolume* vol)
{
  vtkAMRDualMeshVolumeMapper* mapper = this->Mapper;
  vtkAMRDualMeshVolumeMapper::Internals& in = *mapper->Internal;
  // Neither the build nor the transfer-function setup (majorants, culling) is part of the frame.
  const auto start = std::chrono::steady_clock::now();
  int viewport[4] = { 0, 0, 0, 0 }; // x0, y0, width, height
  ren->GetTiledSizeAndOrigin(&viewport[2], &viewport[3], &viewport[0], &viewport[1]);
  const glm::dvec3 o = in.Slot.GetMesh()->sceneOrigin; // the scene frame
  const double origin[3] = { o.x, o.y, o.z };
  amrdm::RenderParams params;
  if (viewport[2] <= 0 || viewport[3] <= 0 ||
      !this->MakeParams(ren, vol, in.Region, origin, viewport[2], viewport[3], true, params))
  {
    return false;
  }
  in.LastRenderInteractive = amrdm_vtk::InteractionPolicy::IsInteractive(
    ren->GetRenderWindow(), mapper->InteractiveUpdateRate);
  const bool ok = in.LastRenderInteractive ? this->RenderInteractive(ren, vol, params, viewport)
                                           : this->RenderStill(ren, vol, params, viewport);
  if (ok || in.LastRenderInteractive)
  {
    mapper->LastRenderSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return ok;
}

//------------------------------------------------------------------------------
bool AMRDualMeshFrameBuilder::RenderStill(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm::RenderParams& params,
  const int viewport[4])
{
  vtkAMRDualMeshVolumeMapper* mapper = this->Mapper;
  vtkAMRDualMeshVolumeMapper::Internals& in = *mapper->Internal;
  amrdm::Renderer& renderer = *in.Slot.GetRenderer();
  amrdm_vtk::AccumulationKey key;
  this->MakeKey(
    ren, vol, in.Compositor, *in.Slot.GetMesh(), params, viewport, in.Slot.GetChangeTime(), key);
  // The surfaces' depth needs this frame's intervals (RenderStill may swap the key).
  std::vector<float> tMin, tMax;
  if (amrdm_vtk::BlendModeHasDepth(params))
  {
    tMin = key.TMin;
    tMax = key.TMax;
  }
  const int maximum = mapper->MaximumSamples;
  const int limit = in.SampleLimit > 0 ? std::min(maximum, in.SampleLimit) : maximum;
  std::string error;
  if (!in.Accum.RenderStill(key,
        renderer,
        params,
        limit,
        mapper->SamplesPerRender,
        mapper->FinalRender ? mapper->FinalRenderTime : 0.0,
        ren->GetRenderWindow(),
        in.Interaction,
        in.LastRenderAborted,
        error))
  {
    vtkErrorWithObjectMacro(
      mapper, "Cannot render a " << params.width << " x " << params.height << " image: " << error);
    return false;
  }
  const std::vector<float>& image = in.Accum.GetImage();
  if (image.size() == std::size_t(4) * viewport[2] * viewport[3])
  {
    in.Compositor.Draw(ren, viewport[2], viewport[3], image.data());
    // Opaque surfaces (Isosurface, Slice) write their depth (AMRDualMeshSurfaceDepth.h).
    double ndcToScene[16];
    vtkMatrix4x4* model = vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix();
    std::vector<float> depth;
    if (amrdm_vtk::BlendModeHasDepth(params) &&
        amrdm_vtk::NdcToScene(ren, model, in.Slot.GetMesh()->sceneOrigin, ndcToScene))
    {
      vtkMatrix4x4::Invert(ndcToScene, ndcToScene); // invertible: NdcToScene checked
      amrdm_vtk::SurfaceDepth(*in.Slot.GetMesh(), params, tMin, tMax, ndcToScene, depth);
      in.Compositor.DrawDepth(ren, viewport[2], viewport[3], depth.data());
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool AMRDualMeshFrameBuilder::RenderInteractive(vtkRenderer* ren,
  vtkVolume* vol,
  const amrdm::RenderParams& params,
  const int viewport[4])
{
  // One cheap frame (AMRDualMeshInteraction.h); the next still render restarts the accumulation.
  vtkAMRDualMeshVolumeMapper* mapper = this->Mapper;
  vtkAMRDualMeshVolumeMapper::Internals& in = *mapper->Internal;
  in.Accum.Invalidate();
  in.Accum.Samples = 0;
  std::string error;
  if (!in.Interaction.RenderFrame(ren,
        *in.Slot.GetRenderer(),
        in.Compositor,
        params,
        viewport,
        mapper->GetClippingPlanes(),
        vol->GetMatrix()->IsIdentity() ? nullptr : vol->GetMatrix(),
        in.Slot.GetMesh()->sceneOrigin,
        mapper->InteractiveFrameTime,
        in.InteractiveReduction,
        error))
  {
    vtkErrorWithObjectMacro(mapper, "Cannot render an interactive frame: " << error);
    return false;
  }
  return true;
}
