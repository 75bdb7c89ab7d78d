// The frame builder of vtkAMRDualMeshVolumeMapper: VTK's view of one frame (the renderer's
// camera, lights and tiled viewport, the vtkVolume's matrix and property, the mapper's
// parameters, clipping planes and region) turned into the kernel's render parameters and, for a
// still frame, the per-pixel ray intervals (opaque depth, clipping planes): together the
// accumulation's reset key (AMRDualMeshAccumulation.h), computed once per frame. Warnings and
// errors are the mapper's. Not wrapped.
#pragma once

#include "AMRDualMeshAccumulation.h"

#include <string>

class vtkAMRDualMeshVolumeMapper;
class vtkRenderer;
class vtkVolume;
namespace amrdm
{
struct DualMesh;
}
namespace amrdm_vtk
{
class Compositor;
class RegionClip;
}

class AMRDualMeshFrameBuilder
{
public:
  explicit AMRDualMeshFrameBuilder(vtkAMRDualMeshVolumeMapper* mapper)
    : Mapper(mapper)
  {
  }

  /// The kernel's parameters of a `width` x `height` frame of `vol` in `ren`, in the scene frame
  /// at `origin` (the dual mesh's). False when the camera's projection composed with the
  /// volume's matrix is singular (an error when `report`).
  bool MakeParams(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm_vtk::RegionClip& region,
    const double origin[3],
    int width,
    int height,
    bool report,
    amrdm::RenderParams& params);

  /// The reset key of a still frame: `params`, the per-pixel intervals of `viewport` (x0, y0,
  /// width, height) from the opaque depth (read through `compositor`) and the clipping planes,
  /// the configuration time, and the renderer slot's `slotTime`.
  void MakeKey(vtkRenderer* ren,
    vtkVolume* vol,
    amrdm_vtk::Compositor& compositor,
    const amrdm::DualMesh& mesh,
    const amrdm::RenderParams& params,
    const int viewport[4],
    vtkMTimeType slotTime,
    amrdm_vtk::AccumulationKey& key);

  /// The reset key without the render-only parts (opaque depth, slot): the view in a scene frame
  /// at the origin (a fixed frame: only changes count) and the configuration time, for a process
  /// that does not render (vtkAMRDualMeshVolumeMapper::GetAccumulationKey()). Quiet.
  void MakeClientKey(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm_vtk::RegionClip& region,
    amrdm_vtk::AccumulationKey& key);

  /// One frame of `vol` in `ren` once the mapper's slots are up to date (a still frame or an
  /// interactive one, AMRDualMeshFrameBuilderPass.cxx); sets the mapper's LastRenderSeconds.
  /// False after an error or for an empty viewport.
  bool Render(vtkRenderer* ren, vtkVolume* vol);

private:
  bool RenderStill(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm::RenderParams& params,
    const int viewport[4]);
  bool RenderInteractive(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm::RenderParams& params,
    const int viewport[4]);

  vtkAMRDualMeshVolumeMapper* Mapper;
  bool WarnedLights = false;
  std::string BlendWarning; ///< the last blend-mode warning (AMRDualMeshBlendMode.h): said once
};
