// The VTK scene in the renderer's terms: vtkVolumeProperty -> amrdm::TransferFunction and the
// vtkRenderer's lights -> amrdm::Light (the camera rays and per-pixel ray intervals are in
// AMRDualMeshProjection.h). Private to vtkAMRDualMeshVolumeMapper;
// not wrapped.
#ifndef AMRDualMeshSceneConversion_h
#define AMRDualMeshSceneConversion_h

#include "transport/Lights.h"
#include "sampling/TransferFunction.h"

#include <string>
#include <vector>

class vtkRenderer;
class vtkVolumeProperty;

namespace amrdm_vtk
{
/// Entries of the RGBA table sampled from the property's functions.
constexpr int kTransferFunctionTableSize = 256;

/// Samples component 0 of `property` (colour or gray function, scalar opacity function) into a
/// kTransferFunctionTableSize-entry table over the union of the two functions' ranges; the unit
/// distance is GetScalarOpacityUnitDistance(0). When the colour function has
/// Scale == VTK_CTF_LOG10 (ParaView's UseLogScale) or the opacity function UseLogScale, the
/// table is evenly spaced in log10(value) and tf.logScale is set (tf.lo, tf.hi are then log10
/// of the range); a log scale over a range that is not positive is sampled linearly, with
/// `warning` saying so. Returns false with `error` set when a function has no points.
bool MakeTransferFunction(vtkVolumeProperty* property,
  amrdm::TransferFunction& tf,
  std::string& error,
  std::string& warning);

// Positions go to the renderer in the scene frame, world - sceneOrigin (DualMesh::sceneOrigin),
// subtracted in double before they become float: a scene at 1e6 with 1e-6 cells renders as it
// does at the origin.

/// The switched-on lights of `renderer` in world space (headlights and camera lights through
/// their transform). Irradiance = pi * intensity (see vtkAMRDualMeshVolumeMapper.h); positional
/// lights become point lights delivering that irradiance at their focal point. Fills at most
/// `maxLights` and returns the number of switched-on lights found (may exceed maxLights).
/// Point-light positions are in the scene frame.
int MakeLights(vtkRenderer* renderer,
  amrdm::Light* lights,
  int maxLights,
  int& used,
  const glm::dvec3& sceneOrigin);

}

#endif
