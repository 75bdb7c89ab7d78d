// Shared by the rendering-extremes tests (TestRenderExtremes, TestRenderExtremesImage): a
// two-level hierarchy on a power-of-two lattice, transfer functions, a view with one fixed ray
// per pixel, and the independent references: a quadrature of the field along a pixel's ray and
// the medium the CPU renderer builds (for per-sample references).
#pragma once

#include <doctest/doctest.h>

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "transport/Integrators.h"

#include <cmath>
#include <vector>

namespace amrdm_test
{
using namespace amrdm;

/// Two levels (ratio 2) on a power-of-two lattice: two root blocks of 8x16x16 cells (width 2 in
/// finest units) and a refined box, spacing 1/8, so every cell centre (dual-mesh vertex), face
/// and element corner has an exact float world coordinate. Dual-cell faces lie on multiples of
/// 0.5 finest cells.
inline DualMesh twoLevelMesh()
{
  AmrHierarchy amr;
  amr.ratio = { 1, 2 };
  auto addBlock = [&](int level, glm::ivec3 lower, glm::ivec3 dims)
  {
    AmrBlock b;
    b.level = level;
    b.lower = lower;
    b.dims = dims;
    const double w = level == 0 ? 2.0 : 1.0;
    for (int z = 0; z < dims.z; ++z)
      for (int y = 0; y < dims.y; ++y)
        for (int x = 0; x < dims.x; ++x)
        {
          const glm::dvec3 p = (glm::dvec3(lower + glm::ivec3(x, y, z)) + 0.5) * w;
          b.values.push_back(float(0.5 + 0.35 * std::sin(0.21 * p.x + 0.3) * std::cos(0.17 * p.y) +
                                   0.1 * std::sin(0.13 * p.z)));
        }
    amr.blocks.push_back(std::move(b));
  };
  addBlock(0, glm::ivec3(0), glm::ivec3(8, 16, 16));
  addBlock(0, glm::ivec3(8, 0, 0), glm::ivec3(8, 16, 16));
  addBlock(1, glm::ivec3(10, 8, 6), glm::ivec3(12, 14, 16));
  amr.origin = glm::dvec3(-1.0, 0.5, 2.0);
  amr.finestSpacing = glm::dvec3(0.125);
  amr.validate();
  amr.finalizeCellStates();
  return buildDualMesh(amr);
}

inline void worldBounds(const DualMesh& mesh, glm::vec3& lo, glm::vec3& hi)
{
  mesh.gridBounds(lo, hi);
  lo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * lo;
  hi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * hi;
}

inline TransferFunction table(std::vector<glm::vec4> entries,
  float lo,
  float hi,
  float unitDistance)
{
  TransferFunction tf;
  tf.table = std::move(entries);
  tf.lo = lo;
  tf.hi = hi;
  tf.unitDistance = unitDistance;
  return tf;
}

/// Opacity 0 below 0.3, rising to 0.9 at 0.9; coloured albedo.
inline TransferFunction rampTf(float unitDistance)
{
  return table({ glm::vec4(0.9f, 0.6f, 0.3f, 0.0f),
                 glm::vec4(0.9f, 0.6f, 0.3f, 0.0f),
                 glm::vec4(0.5f, 0.8f, 0.4f, 0.3f),
                 glm::vec4(0.3f, 0.5f, 0.9f, 0.6f),
                 glm::vec4(0.8f, 0.8f, 0.8f, 0.9f) },
    0.1f,
    0.9f,
    unitDistance);
}

/// Perspective view of the whole mesh, one fixed ray per pixel (pixel centres).
inline RenderParams view(const DualMesh& mesh, int size)
{
  glm::vec3 lo, hi;
  worldBounds(mesh, lo, hi);
  const glm::vec3 centre = 0.5f * (lo + hi);
  RenderParams p;
  p.width = p.height = size;
  p.camera.direction = glm::normalize(glm::vec3(-0.4f, -0.3f, -1.0f));
  p.camera.position = centre - p.camera.direction * (1.3f * glm::length(hi - lo));
  p.camera.viewAngle = 30.0f;
  p.pixelJitter = false;
  p.numLights = 1;
  p.lights[0].direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.5f));
  p.lights[0].intensity = 2.0f;
  p.ambient = glm::vec3(0.5f);
  p.threads = 2;
  return p;
}

/// Quadrature (midpoint, n steps over the mesh bounds) along one pixel's ray: optical depth, and
/// whether a connected run of data crosses [a, b] completely or comes within `margin` of it.
struct RayQuadrature
{
  double tau = 0.0;
  bool crosses = false, near = false;
};
inline RayQuadrature integrate(const DualMesh& mesh,
  const TransferFunction& tf,
  const RenderParams& p,
  int px,
  int py,
  int n,
  float a = 0.0f,
  float b = -1.0f,
  float margin = 0.0f)
{
  RayQuadrature q;
  const Ray ray = generateCameraRay(p.camera, p.width, p.height, px, py, glm::vec2(0.5f));
  glm::vec3 lo, hi;
  worldBounds(mesh, lo, hi);
  float t0 = 0.0f, t1 = kInfinity;
  if (!clipRayToBox(ray, lo, hi, t0, t1))
    return q;
  const DualMeshView mv = mesh.view();
  const TransferFunctionView tv = tf.view();
  float runMin = 1e30f, runMax = -1e30f;
  auto endRun = [&]()
  {
    q.crosses = q.crosses || (runMin < a && runMax > b);
    q.near = q.near || (runMax >= a - margin && runMin <= b + margin);
    runMin = 1e30f, runMax = -1e30f;
  };
  const double dt = (double(t1) - t0) / n;
  for (int i = 0; i < n; ++i)
  {
    const glm::vec3 w = ray.at(float(t0 + (i + 0.5) * dt));
    const glm::vec3 g = (w - glm::vec3(mesh.origin)) / glm::vec3(mesh.finestSpacing);
    float v;
    if (sampleField(mv, g, ElementTestParams(), v))
    {
      q.tau += double(tfExtinction(tv, v)) * dt;
      runMin = std::min(runMin, v);
      runMax = std::max(runMax, v);
    }
    else if (runMin <= runMax)
      endRun();
  }
  endRun();
  return q;
}

inline bool allFinite(const std::vector<float>& image)
{
  for (float v : image)
    if (!std::isfinite(v))
      return false;
  return true;
}

/// Mean alpha of `image` against the mean of 1 - exp(-scale tau) over pixels, within 3 standard
/// errors (the renderer's own variance) plus `slack`.
inline void checkCoverage(const CpuRenderer& r,
  const std::vector<double>& tau,
  double scale,
  double slack)
{
  const std::vector<float> img = r.image(), var = r.varianceOfMean();
  double mean = 0.0, exact = 0.0, variance = 0.0;
  const double n = double(tau.size());
  for (std::size_t i = 0; i < tau.size(); ++i)
  {
    mean += img[4 * i + 3] / n;
    exact += -std::expm1(-scale * tau[i]) / n;
    variance += var[4 * i + 3] / (n * n);
  }
  int wrong = 0;
  for (std::size_t i = 0; i < tau.size(); ++i)
    wrong += std::fabs(img[4 * i + 3] + std::expm1(-scale * tau[i])) > 0.5;
  MESSAGE("mean alpha ",
    mean,
    " vs quadrature ",
    exact,
    " (+- ",
    std::sqrt(variance),
    "), pixels off by > 0.5: ",
    wrong);
  CHECK(std::fabs(mean - exact) <= 3.0 * std::sqrt(variance) + slack);
}

} // namespace amrdm_test
