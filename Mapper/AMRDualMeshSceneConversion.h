// The VTK scene in the renderer's terms: vtkVolumeProperty -> amrdm::TransferFunction,
// vtkCamera -> amrdm::CameraParams, the vtkRenderer's lights -> amrdm::Light, and per-pixel ray
// intervals from the depth buffer and the clipping planes. Private to vtkAMRDualMeshVolumeMapper;
// not wrapped.
#ifndef AMRDualMeshSceneConversion_h
#define AMRDualMeshSceneConversion_h

#include "Camera.h"
#include "Lights.h"
#include "TransferFunction.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkPlaneCollection;
class vtkRenderer;
class vtkVolumeProperty;

namespace amrdm_vtk
{
/// Entries of the RGBA table sampled from the property's functions.
constexpr int kTransferFunctionTableSize = 256;

/// Samples component 0 of `property` (colour or gray function, scalar opacity function) into a
/// kTransferFunctionTableSize-entry table over the union of the two functions' ranges; the unit
/// distance is GetScalarOpacityUnitDistance(0). Returns false with `error` set when a function
/// has no points.
bool MakeTransferFunction(vtkVolumeProperty* property,
  amrdm::TransferFunction& tf,
  std::string& error);

// Positions go to the renderer in the scene frame, world - sceneOrigin (DualMesh::sceneOrigin),
// subtracted in double before they become float: a scene at 1e6 with 1e-6 cells renders as it
// does at the origin.

/// Camera for an image of aspect width / height (vtkCamera conventions; a horizontal view
/// angle is converted to the vertical one), positioned in the scene frame.
amrdm::CameraParams MakeCamera(vtkCamera* camera, double aspect, const glm::dvec3& sceneOrigin);

/// The switched-on lights of `renderer` in world space (headlights and camera lights through
/// their transform). Irradiance = pi * intensity (see vtkAMRDualMeshVolumeMapper.h); positional
/// lights become point lights delivering that irradiance at their focal point. Fills at most
/// `maxLights` and returns the number of switched-on lights found (may exceed maxLights).
/// Point-light positions are in the scene frame.
int MakeLights(vtkRenderer* renderer, amrdm::Light* lights, int maxLights, int& used,
  const glm::dvec3& sceneOrigin);

/// Per-pixel interval [tMin, tMax] along each pixel-centre camera ray (unit direction, as
/// generateCameraRay with jitter 0.5). `depth` (may be null): width*height window depths in
/// [0, 1] (1 = nothing drawn), converted to distances with the inverse of the composite
/// projection matrix `invProjection` (16 doubles, row-major, NDC -> world). `planes` (may be
/// null): each keeps the side its normal points to. An empty interval is written as
/// tMin = tMax = 0. `camera` is in the scene frame (MakeCamera); world positions from the depth
/// buffer and the planes are moved there by subtracting `sceneOrigin` in double.
void ComputeRayIntervals(const amrdm::CameraParams& camera,
  int width,
  int height,
  const float* depth,
  const double invProjection[16],
  vtkPlaneCollection* planes,
  const glm::dvec3& sceneOrigin,
  std::vector<float>& tMin,
  std::vector<float>& tMax);
}

#endif
