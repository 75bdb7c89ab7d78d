// VTK scene -> renderer terms. See AMRDualMeshSceneConversion.h.
#include "AMRDualMeshSceneConversion.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>

namespace amrdm_vtk
{

bool MakeTransferFunction(vtkVolumeProperty* property,
  amrdm::TransferFunction& tf,
  std::string& error)
{
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
  const int n = kTransferFunctionTableSize;
  std::vector<double> rgb(3 * n), gv(n), alpha(n);
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
  tf.table.resize(n);
  for (int i = 0; i < n; ++i)
  {
    tf.table[i] = glm::vec4(float(rgb[3 * i]),
      float(rgb[3 * i + 1]),
      float(rgb[3 * i + 2]),
      float(std::clamp(alpha[i], 0.0, 1.0)));
  }
  tf.lo = float(lo);
  tf.hi = float(hi);
  tf.unitDistance = float(std::max(property->GetScalarOpacityUnitDistance(0), 1e-30));
  return true;
}

amrdm::CameraParams MakeCamera(vtkCamera* camera, double aspect, const glm::dvec3& sceneOrigin)
{
  amrdm::CameraParams cam;
  double p[3], f[3], up[3];
  camera->GetPosition(p);
  camera->GetFocalPoint(f);
  camera->GetViewUp(up);
  cam.position = glm::vec3(glm::dvec3(p[0], p[1], p[2]) - sceneOrigin);
  cam.direction = glm::vec3(glm::normalize(glm::dvec3(f[0] - p[0], f[1] - p[1], f[2] - p[2])));
  cam.up = glm::vec3(up[0], up[1], up[2]);
  cam.parallel = camera->GetParallelProjection() != 0;
  double angle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle() && aspect > 0.0)
  {
    angle = 2.0 * std::atan(std::tan(0.5 * angle * M_PI / 180.0) / aspect) * 180.0 / M_PI;
  }
  cam.viewAngle = float(angle);
  cam.parallelScale = float(camera->GetParallelScale());
  return cam;
}

int MakeLights(vtkRenderer* renderer, amrdm::Light* lights, int maxLights, int& used,
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

void ComputeRayIntervals(const amrdm::CameraParams& camera,
  int width,
  int height,
  const float* depth,
  const double invProjection[16],
  vtkPlaneCollection* planes,
  const glm::dvec3& sceneOrigin,
  std::vector<float>& tMin,
  std::vector<float>& tMax)
{
  const std::size_t n = static_cast<std::size_t>(width) * height;
  tMin.assign(n, 0.0f);
  tMax.assign(n, amrdm::kInfinity);
  // Plane equations n.x + d >= 0 keeps a point.
  std::vector<glm::dvec4> eqs;
  if (planes)
  {
    vtkCollectionSimpleIterator it;
    planes->InitTraversal(it);
    while (vtkPlane* plane = planes->GetNextPlane(it))
    {
      double nrm[3], o[3];
      plane->GetNormal(nrm);
      plane->GetOrigin(o);
      const glm::dvec3 nv(nrm[0], nrm[1], nrm[2]);
      eqs.emplace_back(nv, -glm::dot(nv, glm::dvec3(o[0], o[1], o[2]) - sceneOrigin));
    }
  }
  const double* m = invProjection;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      const amrdm::Ray ray = amrdm::generateCameraRay(camera, width, height, x, y, glm::vec2(0.5f));
      const glm::dvec3 o(ray.o), d(ray.d);
      double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
      if (depth && depth[pixel] < 1.0f)
      {
        const double ndc[4] = { 2.0 * (x + 0.5) / width - 1.0,
          2.0 * (y + 0.5) / height - 1.0,
          2.0 * double(depth[pixel]) - 1.0,
          1.0 };
        double w[4];
        for (int r = 0; r < 4; ++r)
        {
          w[r] = m[4 * r] * ndc[0] + m[4 * r + 1] * ndc[1] + m[4 * r + 2] * ndc[2] + m[4 * r + 3];
        }
        if (w[3] != 0.0)
        {
          const glm::dvec3 surface =
            glm::dvec3(w[0] / w[3], w[1] / w[3], w[2] / w[3]) - sceneOrigin;
          t1 = std::max(0.0, glm::dot(surface - o, d));
        }
      }
      for (const glm::dvec4& e : eqs)
      {
        const glm::dvec3 nv(e);
        const double f0 = glm::dot(nv, o) + e.w, fd = glm::dot(nv, d);
        if (fd > 0.0)
        {
          t0 = std::max(t0, -f0 / fd);
        }
        else if (fd < 0.0)
        {
          t1 = std::min(t1, -f0 / fd);
        }
        else if (f0 < 0.0)
        {
          t1 = -1.0;
        }
      }
      if (!(t0 < t1))
      {
        tMin[pixel] = tMax[pixel] = 0.0f;
        continue;
      }
      tMin[pixel] = float(t0);
      tMax[pixel] = std::isinf(t1) ? amrdm::kInfinity : float(t1);
    }
  }
}
}
