// The window depth of the opaque surfaces that the Isosurface and Slice blend modes draw, so that
// the compositor (AMRDualMeshCompositor) writes it into the depth buffer: geometry drawn after
// the volume, the z-buffer's readers (picking, hover) and later passes then see the surface where
// it is. Computed on the CPU at each pixel centre from the dual mesh (the first isosurface
// crossing by findIsoHit, Kernels/transport/Isosurface.h; the slice plane where the field has a
// value), inside the pixel's ray interval (opaque depth, clipping planes), whatever device draws
// the colours. Private to vtkAMRDualMeshVolumeMapper; not wrapped.
#ifndef AMRDualMeshSurfaceDepth_h
#define AMRDualMeshSurfaceDepth_h

#include "render/RenderParams.h"

#include <vector>

namespace amrdm
{
struct DualMesh;
}

namespace amrdm_vtk
{
/// True for the blend modes whose frames are opaque surfaces with a depth (Isosurface, Slice).
bool BlendModeHasDepth(const amrdm::RenderParams& params);

/// Per-pixel window depth in [0, 1] (1 = no surface) of params.width x params.height pixel-centre
/// rays of params.camera in [tMin, tMax] (ComputeRayIntervals; an empty interval is skipped):
/// the first isosurface crossing of params.isoValues (Isosurface) or the slice plane where the
/// field has a value (Slice), projected with `sceneToNdc` (row-major 4x4, the inverse of
/// NdcToScene's matrix; window depth = (ndc z + 1) / 2). False, depth empty, for another mode.
bool SurfaceDepth(const amrdm::DualMesh& mesh,
  const amrdm::RenderParams& params,
  const std::vector<float>& tMin,
  const std::vector<float>& tMax,
  const double sceneToNdc[16],
  std::vector<float>& depth);
}

#endif
