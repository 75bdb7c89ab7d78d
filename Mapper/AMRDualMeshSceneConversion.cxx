// VTK scene -> renderer terms. See AMRDualMeshSceneConversion.h.
#include "AMRDualMeshSceneConversion.h"

#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace amrdm_vtk
{

bool MakeTransferFunction(vtkVolumeProperty* property,
  amrdm::TransferFunction& tf,
  std::string& error,
  std::string& warning)
{
  warning.clear();
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const bool gray = property->GetColorChannels(0) == 1;
  vtkColorTransferFunction* color = gray ? nullptr : property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* grayFunction = gray ? property->GetGrayTransferFunction(0) : nullptr;
  if (!opacity || opacity->GetSize() == 0)
  {
    error = "the volume property's scalar opacity function has no points";
    return false;
  }
  if ((color && color->GetSize() == 0) || (grayFunction && grayFunction->GetSize() == 0))
  {
    error = "the volume property's colour transfer function has no points";
    return false;
  }
  double lo = opacity->GetRange()[0], hi = opacity->GetRange()[1];
  const double* colorRange = color ? color->GetRange() : grayFunction->GetRange();
  lo = std::min(lo, colorRange[0]);
  hi = std::max(hi, colorRange[1]);
  if (!(hi > lo))
  {
    hi = lo + 1.0; // a single point: constant table
  }
  // Log scale (vtkColorTransferFunction::SetScale(VTK_CTF_LOG10), e.g. ParaView's UseLogScale,
  // or vtkPiecewiseFunction::UseLogScale): entries evenly spaced in log10(value), each the
  // functions' own value there (so their log-space interpolation between nodes is kept); the
  // kernel looks values up by log10. Needs a positive domain, as VTK's own log scale does.
  const bool logRequested =
    (color && color->GetScale() == VTK_CTF_LOG10) || opacity->GetUseLogScale();
  tf.logScale = logRequested && lo > 0.0;
  if (logRequested && !tf.logScale)
  {
    warning = "log scale needs a positive transfer-function range, got [" + std::to_string(lo) +
              ", " + std::to_string(hi) + "]; the functions are sampled on a linear scale";
  }
  const int n = kTransferFunctionTableSize;
  std::vector<double> rgb(3 * n), gv(n), alpha(n);
  if (tf.logScale)
  {
    const double logLo = std::log10(lo), logHi = std::log10(hi);
    for (int i = 0; i < n; ++i)
    {
      // The end entries are the range ends exactly (pow(10, log10(x)) may round off them).
      const double x = i == 0       ? lo
                       : i == n - 1 ? hi
                                    : std::pow(10.0, logLo + (logHi - logLo) * i / (n - 1.0));
      if (color)
      {
        color->GetColor(x, &rgb[3 * i]);
      }
      else
      {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = grayFunction->GetValue(x);
      }
      alpha[i] = opacity->GetValue(x);
    }
  }
  else
  {
    if (color)
    {
      color->GetTable(lo, hi, n, rgb.data());
    }
    else
    {
      grayFunction->GetTable(lo, hi, n, gv.data());
      for (int i = 0; i < n; ++i)
      {
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = gv[i];
      }
    }
    opacity->GetTable(lo, hi, n, alpha.data());
  }
  tf.table.resize(n);
  for (int i = 0; i < n; ++i)
  {
    tf.table[i] = glm::vec4(float(rgb[3 * i]),
      float(rgb[3 * i + 1]),
      float(rgb[3 * i + 2]),
      float(std::clamp(alpha[i], 0.0, 1.0)));
  }
  if (tf.logScale)
  {
    lo = std::log10(lo);
    hi = std::log10(hi);
  }
  tf.lo = float(lo);
  tf.hi = float(hi);
  tf.unitDistance = float(std::max(property->GetScalarOpacityUnitDistance(0), 1e-30));
  return true;
}

int MakeLights(vtkRenderer* renderer,
  amrdm::Light* lights,
  int maxLights,
  int& used,
  const glm::dvec3& sceneOrigin)
{
  used = 0;
  int found = 0;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch() || !(light->GetIntensity() > 0.0))
    {
      continue;
    }
    ++found;
    if (used >= maxLights)
    {
      continue;
    }
    double p[3], f[3], c[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    light->GetDiffuseColor(c);
    const glm::dvec3 pos(p[0], p[1], p[2]), focal(f[0], f[1], f[2]);
    amrdm::Light& out = lights[used++];
    out.color = glm::vec3(c[0], c[1], c[2]);
    const double irradiance = M_PI * light->GetIntensity();
    if (light->GetPositional())
    {
      const glm::dvec3 d = pos - focal;
      out.type = amrdm::LightType::Point;
      out.position = glm::vec3(pos - sceneOrigin);
      out.intensity = float(irradiance * std::max(glm::dot(d, d), 1e-30));
    }
    else
    {
      glm::dvec3 d = pos - focal;
      const double len = glm::length(d);
      out.type = amrdm::LightType::Directional;
      out.direction = len > 0.0 ? glm::vec3(d / len) : glm::vec3(0.0f, 0.0f, 1.0f);
      out.intensity = float(irradiance);
    }
  }
  return found;
}
}
