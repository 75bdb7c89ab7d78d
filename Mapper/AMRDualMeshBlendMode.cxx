#include "AMRDualMeshBlendMode.h"

#include <vtkAbstractTransform.h>
#include <vtkContourValues.h>
#include <vtkPlane.h>
#include <vtkVolumeMapper.h>
#include <vtkVolumeProperty.h>

#include "vtkAMRDualMeshVolumeMapper.h"

#include <algorithm>
#include <cmath>

static_assert(
  int(amrdm::BlendMode::Composite) == vtkVolumeMapper::COMPOSITE_BLEND &&
    int(amrdm::BlendMode::MaximumIntensity) == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND &&
    int(amrdm::BlendMode::MinimumIntensity) == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND &&
    int(amrdm::BlendMode::AverageIntensity) == vtkVolumeMapper::AVERAGE_INTENSITY_BLEND &&
    int(amrdm::BlendMode::Additive) == vtkVolumeMapper::ADDITIVE_BLEND &&
    int(amrdm::BlendMode::Isosurface) == vtkVolumeMapper::ISOSURFACE_BLEND &&
    int(amrdm::BlendMode::Slice) == vtkVolumeMapper::SLICE_BLEND &&
    amrdm::kBlendModeCount == vtkVolumeMapper::SLICE_BLEND + 1,
  "render/BlendModeList.h must list vtkVolumeMapper's blend modes with VTK's values");

namespace amrdm_vtk
{
std::string ApplyBlendMode(vtkVolumeMapper* mapper,
  vtkVolumeProperty* property,
  const glm::dvec3& sceneOrigin,
  amrdm::RenderParams& params)
{
  const int vtkMode = mapper->GetBlendMode();
  if (vtkMode < 0 || vtkMode >= amrdm::kBlendModeCount)
  {
    params.blendMode = amrdm::BlendMode::Composite;
    return "BlendMode " + std::to_string(vtkMode) +
           " is not one of vtkVolumeMapper's blend modes (0..6); rendering Composite.";
  }
  params.blendMode = amrdm::BlendMode(vtkMode);
  const std::string mode =
    std::string("BlendMode ") + amrdm::blendModeInfo(params.blendMode).vtkName;
  // The mode the user set is what renders (a ParaView Volume script sets BlendMode alone): an
  // integrator that draws Composite only hands the frame to the ray marcher, said once.
  std::string note;
  const auto add = [&note](const std::string& sentence)
  { note += note.empty() ? sentence : " " + sentence; };
  if (amrdm::blendModeLimitation(params.integrator, params.blendMode))
  {
    add(mode + " is drawn by the ray-march integrator (Integrator " +
        amrdm::integratorInfo(params.integrator).vtkName +
        " draws Composite only); set Integrator to RAY_MARCH to silence this.");
    params.integrator = amrdm::IntegratorType::RayMarch;
  }
  double range[2] = { 0.0, 0.0 };
  mapper->GetAverageIPScalarRange(range);
  params.averageRangeLo = float(std::max(range[0], -3.0e38));
  params.averageRangeHi = float(std::min(range[1], 3.0e38));
  // EmbedIsosurfaces (a property of this mapper beyond VTK's modes): Composite with the
  // property's iso values drawn inside the volume.
  auto* own = vtkAMRDualMeshVolumeMapper::SafeDownCast(mapper);
  params.embedIsosurfaces =
    own && own->GetEmbedIsosurfaces() != 0 && params.blendMode == amrdm::BlendMode::Composite;
  if (const char* embed =
        amrdm::embedIsosurfacesLimitation(params.integrator, params.embedIsosurfaces))
  {
    add(std::string(embed) + ".");
    params.embedIsosurfaces = false;
  }
  if (params.blendMode == amrdm::BlendMode::Isosurface || params.embedIsosurfaces)
  {
    vtkContourValues* values = property->GetIsoSurfaceValues();
    const int n = values ? values->GetNumberOfContours() : 0;
    params.numIsoValues = std::min(n, amrdm::kMaxIsoValues);
    for (int i = 0; i < params.numIsoValues; ++i)
    {
      params.isoValues[i] = float(values->GetValue(i));
    }
    if (n == 0)
    {
      add((params.embedIsosurfaces ? std::string("EmbedIsosurfaces") : mode) +
          " with no isosurface value (vtkVolumeProperty::GetIsoSurfaceValues()): " +
          (params.embedIsosurfaces ? "the volume alone is drawn." : "nothing is drawn."));
    }
    else if (n > amrdm::kMaxIsoValues)
    {
      add(mode + ": " + std::to_string(n) + " isosurface values; the first " +
          std::to_string(amrdm::kMaxIsoValues) + " are drawn.");
    }
  }
  if (params.blendMode == amrdm::BlendMode::Slice)
  {
    vtkPlane* plane = vtkPlane::SafeDownCast(property->GetSliceFunction());
    if (!plane)
    {
      params.sliceNormal = glm::vec3(0.0f);
      add(mode + (property->GetSliceFunction()
                     ? " needs a vtkPlane as the slice function; nothing is drawn."
                     : " with no slice function (vtkVolumeProperty::SetSliceFunction, a "
                       "vtkPlane): nothing is drawn."));
      return note;
    }
    double o[3], n[3];
    plane->GetOrigin(o);
    plane->GetNormal(n);
    const glm::dvec3 normal(n[0], n[1], n[2]);
    if (!(glm::length(normal) > 0.0))
    {
      params.sliceNormal = glm::vec3(0.0f);
      add(mode + ": the slice plane's normal is zero; nothing is drawn.");
      return note;
    }
    params.sliceOrigin = glm::vec3(glm::dvec3(o[0], o[1], o[2]) - sceneOrigin);
    params.sliceNormal = glm::vec3(glm::normalize(normal));
    if (plane->GetTransform())
    {
      add(mode + ": the slice plane's own Transform is not applied (the plane is taken in "
                 "the volume's data frame).");
    }
  }
  return note;
}

bool SameBlend(const amrdm::RenderParams& a, const amrdm::RenderParams& b)
{
  if (a.blendMode != b.blendMode || a.embedIsosurfaces != b.embedIsosurfaces ||
      a.numIsoValues != b.numIsoValues || a.sliceOrigin != b.sliceOrigin ||
      a.sliceNormal != b.sliceNormal || a.averageRangeLo != b.averageRangeLo ||
      a.averageRangeHi != b.averageRangeHi)
  {
    return false;
  }
  return std::equal(a.isoValues, a.isoValues + a.numIsoValues, b.isoValues);
}
}
