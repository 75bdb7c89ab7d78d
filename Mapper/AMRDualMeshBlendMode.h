// vtkVolumeMapper's blend modes in the renderer's terms: the mapper's BlendMode (same values as
// amrdm::BlendMode, render/BlendModeList.h), vtkVolumeProperty::GetIsoSurfaceValues() and
// GetSliceFunction() (a vtkPlane, in the volume's data frame, as VTK's GPU mapper reads it) and
// vtkVolumeMapper::GetAverageIPScalarRange() -> amrdm::RenderParams. Private to
// vtkAMRDualMeshVolumeMapper; not wrapped.
#ifndef AMRDualMeshBlendMode_h
#define AMRDualMeshBlendMode_h

#include "render/RenderParams.h"

#include <string>

class vtkVolumeMapper;
class vtkVolumeProperty;

namespace amrdm_vtk
{
/// Sets params.blendMode and what the mode reads (iso values, slice plane in the scene frame =
/// data frame - sceneOrigin, average range) from `mapper` and `property`; params.integrator must
/// be set: an integrator that draws Composite only is replaced by RayMarch for a non-composite
/// mode (the mode the user set is what renders). Returns what the mapper warns with once: that
/// switch, no iso value, more than kMaxIsoValues, no or a non-plane slice function, a blend mode
/// outside VTK's list; empty when the mode is drawn as asked by the integrator asked.
std::string ApplyBlendMode(vtkVolumeMapper* mapper,
  vtkVolumeProperty* property,
  const glm::dvec3& sceneOrigin,
  amrdm::RenderParams& params);

/// Whether two frames' blend-mode parameters draw the same image (the accumulation restarts when
/// they do not).
bool SameBlend(const amrdm::RenderParams& a, const amrdm::RenderParams& b);
}

#endif
