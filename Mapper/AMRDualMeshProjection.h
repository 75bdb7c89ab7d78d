// The rays of the projection VTK draws with: the renderer's composite projection for its tiled
// viewport (vtkOpenGLCamera's key matrix: window centre, view shear, tiles of
// vtkWindowToImageFilter / vtkRenderLargeImage / ParaView screenshots, explicit projections),
// composed with the vtkVolume's matrix, unprojected into the dual mesh's scene frame; and the
// per-pixel ray intervals that the depth buffer and the clipping planes leave. Private to
// vtkAMRDualMeshVolumeMapper; not wrapped.
#ifndef AMRDualMeshProjection_h
#define AMRDualMeshProjection_h

#include "core/Camera.h"
#include "transport/Lights.h"

#include <vector>

class vtkMatrix4x4;
class vtkPlaneCollection;
class vtkRenderer;

namespace amrdm_vtk
{
/// Row-major 4x4 that maps normalised device coordinates of `renderer`'s tiled viewport
/// (x, y, depth in [-1, 1]) to the scene frame: data coordinates of the volume (through the
/// inverse of `model`, the vtkVolume's data -> world matrix; null = identity) minus
/// `sceneOrigin` (DualMesh::sceneOrigin), all in double. Returns false when the composite matrix
/// is singular (e.g. a volume scale of 0).
bool NdcToScene(vtkRenderer* renderer,
  vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  double ndcToScene[16]);

/// A projective camera (CameraParams::projective) whose rays are those of `ndcToScene`: each
/// starts on the near plane and passes through the far-plane point of the same pixel; exact for
/// every projection whose homogeneous w depends on the view depth only (vtkCamera's perspective
/// and parallel projections with window centre and shear). The classic fields are filled for
/// information (eye and view direction in the scene frame, vtkCamera's angle and scale).
amrdm::CameraParams MakeCamera(vtkRenderer* renderer, const double ndcToScene[16]);

/// The active camera's position (the eye of a perspective projection) in the scene frame:
/// through the inverse of `model` (data -> world; null = identity), minus `sceneOrigin`, in
/// double (CameraParams::anchor). It does not depend on the clipping range.
glm::dvec3 CameraAnchor(vtkRenderer* renderer, vtkMatrix4x4* model, const glm::dvec3& sceneOrigin);

/// Per-pixel interval [tMin, tMax] along each pixel-centre camera ray of `camera` (as
/// generateCameraRay with jitter 0.5). `depth` (may be null): width*height window depths in
/// [0, 1] (1 = nothing drawn) of the tiled viewport, unprojected with `ndcToScene`. `planes`
/// (may be null; world coordinates, as VTK's volume mappers take them): each keeps the side its
/// normal points to; they are moved into the scene frame through `model` (data -> world; null =
/// identity) and `sceneOrigin`. An empty interval is written as tMin = tMax = 0.
void ComputeRayIntervals(const amrdm::CameraParams& camera,
  int width,
  int height,
  const float* depth,
  const double ndcToScene[16],
  vtkPlaneCollection* planes,
  vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  std::vector<float>& tMin,
  std::vector<float>& tMax);

/// True when two projective cameras have the same rays up to float rounding (1e-5 relative):
/// vtkWindowToImageFilter renders a grab with a copy of the camera whose view angle went
/// through float, which must not restart an accumulation.
bool SameRays(const amrdm::CameraParams& a, const amrdm::CameraParams& b);

/// Moves `count` lights from the scene frame of world coordinates into the scene frame of the
/// data through the inverse of `model` (data -> world): directions through the inverse linear
/// part (renormalised), point-light positions through the inverse matrix.
void LightsToDataFrame(vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  amrdm::Light* lights,
  int count);

/// True when the intervals describe the same rays within `tolerance` (scene units): a depth
/// buffer re-read by a screenshot re-render need not repeat bit for bit.
bool SameIntervals(const std::vector<float>& aMin,
  const std::vector<float>& aMax,
  const std::vector<float>& bMin,
  const std::vector<float>& bMax,
  float tolerance);
}

#endif
