// Window depth of the Isosurface / Slice surfaces. See AMRDualMeshSurfaceDepth.h.
#include "AMRDualMeshSurfaceDepth.h"

#include "core/Camera.h"
#include "core/ParallelFor.h"
#include "mesh/DualMesh.h"
#include "transport/Isosurface.h"

#include <cmath>

namespace amrdm_vtk
{
bool BlendModeHasDepth(const amrdm::RenderParams& params)
{
  return (params.blendMode == amrdm::BlendMode::Isosurface && params.numIsoValues > 0) ||
         params.blendMode == amrdm::BlendMode::Slice;
}

bool SurfaceDepth(const amrdm::DualMesh& mesh,
  const amrdm::RenderParams& params,
  const std::vector<float>& tMin,
  const std::vector<float>& tMax,
  const double sceneToNdc[16],
  std::vector<float>& depth)
{
  depth.clear();
  const int width = params.width, height = params.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  if (!BlendModeHasDepth(params) || width <= 0 || height <= 0 || tMin.size() != n ||
      tMax.size() != n)
  {
    return false;
  }
  amrdm::DualMeshMedium medium;
  medium.mesh = mesh.view();
  medium.elementTest = params.elementTest;
  medium.origin = glm::vec3(mesh.origin);
  medium.invSpacing = 1.0f / glm::vec3(mesh.finestSpacing);
  // One macrocell over the mesh without value ranges: the isosurface search visits the BVH
  // along the whole interval (no majorant grid is built or needed here).
  glm::vec3 gridLo, gridHi;
  mesh.gridBounds(gridLo, gridHi);
  const float majorant = 0.0f;
  amrdm::MajorantGridView grid;
  grid.res = glm::ivec3(1);
  grid.lo = medium.origin + gridLo / medium.invSpacing;
  grid.hi = medium.origin + gridHi / medium.invSpacing;
  grid.majorant = &majorant;
  const glm::vec3 normal = params.sliceNormal;
  depth.assign(n, 1.0f);
  amrdm::parallelFor(static_cast<std::size_t>(height),
    params.threads,
    [&](std::size_t row)
    {
      const int y = static_cast<int>(row);
      amrdm::TraceCounters counters;
      for (int x = 0; x < width; ++x)
      {
        const std::size_t pixel = row * width + x;
        const float t0 = tMin[pixel], t1 = tMax[pixel];
        if (!(t1 > t0))
        {
          continue;
        }
        const amrdm::Ray ray =
          amrdm::generateCameraRay(params.camera, width, height, x, y, glm::vec2(0.5f));
        float t = amrdm::kInfinity;
        if (params.blendMode == amrdm::BlendMode::Slice)
        {
          const float den = glm::dot(normal, ray.d);
          const float ts = den != 0.0f ? glm::dot(normal, params.sliceOrigin - ray.o) / den : -1.0f;
          float v = 0.0f;
          if (ts >= t0 && ts <= t1 && medium.value(ray.at(ts), v, counters))
          {
            t = ts;
          }
        }
        else
        {
          const amrdm::IsoHit hit = amrdm::findIsoHit(medium,
            grid,
            ray,
            t0,
            t1,
            params.isoValues,
            params.numIsoValues,
            params.stepSize,
            counters);
          t = hit.hit() ? hit.t : amrdm::kInfinity;
        }
        if (!(t < amrdm::kInfinity))
        {
          continue;
        }
        const glm::dvec3 p(ray.at(t));
        const double* m = sceneToNdc;
        const double z = m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11];
        const double w = m[12] * p.x + m[13] * p.y + m[14] * p.z + m[15];
        if (w != 0.0)
        {
          depth[pixel] = static_cast<float>(std::min(1.0, std::max(0.0, 0.5 * (z / w) + 0.5)));
        }
      }
    });
  return true;
}
}
