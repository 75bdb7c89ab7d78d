// Rays of the composite projection. See AMRDualMeshProjection.h.
#include "AMRDualMeshProjection.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amrdm_vtk
{
namespace
{
/// ndcToScene * (x, y, z, 1), divided by w; false when w is 0.
bool Unproject(const double m[16], double x, double y, double z, glm::dvec3& p)
{
  double h[4];
  for (int r = 0; r < 4; ++r)
  {
    h[r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
  }
  if (h[3] == 0.0 || !std::isfinite(h[3]))
  {
    return false;
  }
  p = glm::dvec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
  return true;
}
}

bool NdcToScene(vtkRenderer* renderer,
  vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  double ndcToScene[16])
{
  // What vtkOpenGLCamera::GetKeyMatrices draws geometry with (world -> NDC of the tiled viewport).
  vtkCamera* camera = renderer->GetActiveCamera();
  // Scene -> NDC composed before the inversion, and the view's translation before the
  // projection's scale: the large parts of a far-off scene (the eye's and the origin's
  // translations) cancel in double in modelView * model * T(sceneOrigin), so a 1e-6 cell at 1e6
  // keeps its digits and the inverse stays well conditioned.
  vtkNew<vtkMatrix4x4> sceneToData, sceneToWorld, sceneToEye, full;
  for (int r = 0; r < 3; ++r)
  {
    sceneToData->SetElement(r, 3, sceneOrigin[r]);
  }
  if (model)
  {
    vtkMatrix4x4::Multiply4x4(model, sceneToData, sceneToWorld);
  }
  else
  {
    sceneToWorld->DeepCopy(sceneToData);
  }
  vtkMatrix4x4::Multiply4x4(camera->GetModelViewTransformMatrix(), sceneToWorld, sceneToEye);
  vtkMatrix4x4::Multiply4x4(
    camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0),
    sceneToEye,
    full);
  if (full->Determinant() == 0.0)
  {
    return false;
  }
  full->Invert();
  std::copy(full->GetData(), full->GetData() + 16, ndcToScene);
  for (int i = 0; i < 16; ++i)
  {
    if (!std::isfinite(ndcToScene[i]))
    {
      return false;
    }
  }
  return true;
}

amrdm::CameraParams MakeCamera(vtkRenderer* renderer, const double ndcToScene[16])
{
  amrdm::CameraParams cam;
  // Near- and far-plane points at the centre and one unit along x and y: both are affine in
  // (x, y) for projections whose w depends on depth only, so three points give the whole map.
  glm::dvec3 n[3], f[3];
  const double xs[3] = { 0.0, 1.0, 0.0 }, ys[3] = { 0.0, 0.0, 1.0 };
  for (int i = 0; i < 3; ++i)
  {
    Unproject(ndcToScene, xs[i], ys[i], -1.0, n[i]);
    Unproject(ndcToScene, xs[i], ys[i], 1.0, f[i]);
  }
  const glm::dvec3 d0 = f[0] - n[0], dx = (f[1] - n[1]) - d0, dy = (f[2] - n[2]) - d0;
  // Directions scaled to unit length at the centre keep float components of similar size.
  const double scale = 1.0 / std::max(glm::length(d0), 1e-300);
  cam.projective = true;
  cam.origin0 = glm::vec3(n[0]);
  cam.originX = glm::vec3(n[1] - n[0]);
  cam.originY = glm::vec3(n[2] - n[0]);
  cam.direction0 = glm::vec3(d0 * scale);
  cam.directionX = glm::vec3(dx * scale);
  cam.directionY = glm::vec3(dy * scale);

  vtkCamera* camera = renderer->GetActiveCamera();
  cam.position = cam.origin0;
  cam.direction = cam.direction0;
  cam.up =
    glm::normalize(glm::vec3(glm::length(cam.originY) > 0.0f ? cam.originY : cam.directionY));
  cam.parallel = camera->GetParallelProjection() != 0;
  cam.viewAngle = float(camera->GetViewAngle());
  cam.parallelScale = float(camera->GetParallelScale());
  return cam;
}

glm::dvec3 CameraAnchor(vtkRenderer* renderer, vtkMatrix4x4* model, const glm::dvec3& sceneOrigin)
{
  double p[4] = { 0.0, 0.0, 0.0, 1.0 };
  renderer->GetActiveCamera()->GetPosition(p);
  if (model)
  {
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(model, inverse);
    inverse->MultiplyPoint(p, p);
    for (int i = 0; i < 3; ++i)
    {
      p[i] /= p[3];
    }
  }
  return glm::dvec3(p[0], p[1], p[2]) - sceneOrigin;
}

void ComputeRayIntervals(const amrdm::CameraParams& camera,
  int width,
  int height,
  const float* depth,
  const double ndcToScene[16],
  vtkPlaneCollection* planes,
  vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  std::vector<float>& tMin,
  std::vector<float>& tMax)
{
  const std::size_t n = static_cast<std::size_t>(width) * height;
  tMin.assign(n, 0.0f);
  tMax.assign(n, amrdm::kInfinity);
  // Plane equations n.x + d >= 0 keep a point; world planes moved into the scene frame:
  // x_world = A (x + sceneOrigin) + t gives the normal A^T n and the offset n.(A o + t) + d.
  std::vector<glm::dvec4> eqs;
  if (planes)
  {
    const double* m = model ? model->GetData() : nullptr;
    vtkCollectionSimpleIterator it;
    planes->InitTraversal(it);
    while (vtkPlane* plane = planes->GetNextPlane(it))
    {
      double nrm[3], o[3];
      plane->GetNormal(nrm);
      plane->GetOrigin(o);
      const glm::dvec3 nw(nrm[0], nrm[1], nrm[2]);
      const double dw = -glm::dot(nw, glm::dvec3(o[0], o[1], o[2]));
      glm::dvec3 ns = nw;
      double ds = dw;
      if (m)
      {
        for (int c = 0; c < 3; ++c)
        {
          ns[c] = m[c] * nw[0] + m[4 + c] * nw[1] + m[8 + c] * nw[2];
        }
        ds += m[3] * nw[0] + m[7] * nw[1] + m[11] * nw[2];
      }
      ds += glm::dot(ns, sceneOrigin);
      eqs.emplace_back(ns, ds);
    }
  }
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      const amrdm::Ray ray = amrdm::generateCameraRay(camera, width, height, x, y, glm::vec2(0.5f));
      const glm::dvec3 o(ray.o), d(ray.d);
      double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
      glm::dvec3 surface;
      if (depth && depth[pixel] < 1.0f &&
          Unproject(ndcToScene,
            2.0 * (x + 0.5) / width - 1.0,
            2.0 * (y + 0.5) / height - 1.0,
            2.0 * double(depth[pixel]) - 1.0,
            surface))
      {
        t1 = std::max(0.0, glm::dot(surface - o, d));
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

bool SameIntervals(const std::vector<float>& aMin,
  const std::vector<float>& aMax,
  const std::vector<float>& bMin,
  const std::vector<float>& bMax,
  float tolerance)
{
  if (aMin.size() != bMin.size() || aMax.size() != bMax.size())
  {
    return false;
  }
  const auto close = [tolerance](float a, float b)
  { return a == b || std::fabs(a - b) <= tolerance; }; // kInfinity == kInfinity
  for (std::size_t i = 0; i < aMin.size(); ++i)
  {
    if (!close(aMin[i], bMin[i]) || !close(aMax[i], bMax[i]))
    {
      return false;
    }
  }
  return true;
}

bool SameRays(const amrdm::CameraParams& a, const amrdm::CameraParams& b)
{
  const float scale =
    std::max({ glm::length(a.origin0), glm::length(a.originX), glm::length(a.originY), 1e-30f });
  const auto close = [](const glm::vec3& u, const glm::vec3& v, float s)
  { return glm::length(u - v) <= 1e-5f * s; };
  return a.projective == b.projective && close(a.origin0, b.origin0, scale) &&
         close(a.originX, b.originX, scale) && close(a.originY, b.originY, scale) &&
         close(a.direction0, b.direction0, 1.0f) && close(a.directionX, b.directionX, 1.0f) &&
         close(a.directionY, b.directionY, 1.0f);
}

void LightsToDataFrame(vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  amrdm::Light* lights,
  int count)
{
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(model, inverse);
  const double* m = inverse->GetData();
  for (int i = 0; i < count; ++i)
  {
    amrdm::Light& light = lights[i];
    const glm::dvec3 d(light.direction), p = glm::dvec3(light.position) + sceneOrigin;
    glm::dvec3 dd, pp;
    for (int r = 0; r < 3; ++r)
    {
      dd[r] = m[4 * r] * d.x + m[4 * r + 1] * d.y + m[4 * r + 2] * d.z;
      pp[r] = m[4 * r] * p.x + m[4 * r + 1] * p.y + m[4 * r + 2] * p.z + m[4 * r + 3];
    }
    const double len = glm::length(dd);
    light.direction = len > 0.0 ? glm::vec3(dd / len) : light.direction;
    light.position = glm::vec3(pp - sceneOrigin);
  }
}
}
