// The scene of the transport tests (TestBlendModes, TestIsoFirstHit, TestIsosurfacePathTracer):
// a 3-level synthetic hierarchy over 12 x 10 x 8 root cells, finest grid 48 x 40 x 32 with
// world = grid; the hull of its level-0 cell centres (where the field has data) and its domain
// box (the clamped boundary layer reaches it); random rays; the medium and majorant grid the
// integrators trace through.
#pragma once

#include "mesh/DualMeshBuilder.h"
#include "render/CpuRenderer.h"
#include "transport/Integrators.h"
#include "SyntheticAmr.h"

#include <doctest/doctest.h>

#include <random>

namespace amrdm_test
{
const glm::vec3 kHullLo(2.0f), kHullHi(46.0f, 38.0f, 30.0f); // level-0 cell centres
const glm::vec3 kDomainLo(0.0f), kDomainHi(48.0f, 40.0f, 32.0f);

/// The box layout (3 levels over 12 x 10 x 8 root cells) with cell data `field`.
inline amrdm::AmrHierarchy makeThreeLevelAmr(const Field& field, unsigned seed = 7)
{
  SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(12, 10, 8);
  opt.boxesPerLevel = 4;
  return makeSynthetic(seed, opt, field);
}

/// The dual mesh of makeThreeLevelAmr(field, seed): finest spacing 1, origin 0.
inline amrdm::DualMesh makeThreeLevelMesh(const Field& field, unsigned seed = 7)
{
  amrdm::AmrHierarchy amr = makeThreeLevelAmr(field, seed);
  amr.finalizeCellStates();
  amrdm::DualMesh mesh = amrdm::buildDualMesh(amr);
  REQUIRE(mesh.finestSpacing == glm::dvec3(1.0));
  REQUIRE(mesh.origin == glm::dvec3(0.0));
  return mesh;
}

/// A uniform point of the box [lo, hi].
inline glm::vec3 randomIn(std::mt19937& rng, glm::vec3 lo, glm::vec3 hi)
{
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  return lo + (hi - lo) * glm::vec3(u(rng), u(rng), u(rng));
}

/// A uniform direction.
inline glm::vec3 randomDir(std::mt19937& rng)
{
  std::normal_distribution<float> n;
  return glm::normalize(glm::vec3(n(rng), n(rng), n(rng)));
}

/// The medium and majorant grid of a mesh and transfer function, with default parameters,
/// as the renderers assemble them.
struct MediumScene
{
  amrdm::RenderScene scene;
  amrdm::RenderParams params;
  amrdm::DualMeshMedium medium;
  amrdm::MajorantGridView grid;
  MediumScene(const amrdm::DualMesh& mesh, const amrdm::TransferFunction& tf)
  {
    scene.setMesh(&mesh, glm::ivec3(0), 1);
    scene.setTransferFunction(tf, 1);
    params = scene.resolve(params);
    medium = scene.medium(params);
    grid = scene.majorantGrid().view();
  }
  /// The first crossing of `iso` along `ray` inside the hull (none when the ray misses it).
  amrdm::IsoHit first(const amrdm::Ray& ray, float iso) const
  {
    float t0 = 0.0f, t1 = amrdm::kInfinity;
    amrdm::TraceCounters counters;
    if (!amrdm::clipRayToBox(ray, kHullLo, kHullHi, t0, t1))
      return amrdm::IsoHit();
    return amrdm::findIsoHit(medium, grid, ray, t0, t1, &iso, 1, 1.0f, counters);
  }
};

/// True when the point of the horizontal plane z = q.z lies inside the hull by more than one
/// cell in x and y (where the plane tests compare pixels with the analytic surface).
inline bool insideHullXY(const glm::dvec3& q)
{
  return q.x > kHullLo.x + 1.0 && q.x < kHullHi.x - 1.0 && q.y > kHullLo.y + 1.0 &&
         q.y < kHullHi.y - 1.0;
}
} // namespace amrdm_test
