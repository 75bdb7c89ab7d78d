// The scene of the sampling tests (TestCompositeMedium, TestRayHints): a 3-level synthetic
// hierarchy over 10 x 8 x 7 root cells with a smooth field, off the origin and with unequal
// spacing; a four-entry transfer function; the dual-mesh medium of a mesh and its world bounds.
#pragma once

#include "mesh/DualMeshBuilder.h"
#include "sampling/Media.h"
#include "SyntheticAmr.h"

#include <cmath>

namespace amrdm_test
{

inline float samplingField(const glm::dvec3& p)
{
  return static_cast<float>(
    0.5 + 0.5 * std::sin(0.15 * p.x) * std::cos(0.2 * p.y) * std::sin(0.1 * p.z + 1.0));
}

/// The hierarchy of `seed` (validated, cell states final).
inline amrdm::AmrHierarchy samplingHierarchy(unsigned seed)
{
  SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(10, 8, 7);
  opt.boxesPerLevel = 4;
  opt.maxBoxCells = 8;
  amrdm::AmrHierarchy amr = makeSynthetic(seed, opt, samplingField);
  amr.origin = glm::dvec3(-1.0, 2.0, 0.5);
  amr.finestSpacing = glm::dvec3(0.1, 0.1, 0.12);
  amr.validate();
  amr.finalizeCellStates();
  return amr;
}

inline amrdm::TransferFunction samplingTf()
{
  amrdm::TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.0f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.3f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.7f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.95f) };
  tf.lo = 0.2f;
  tf.hi = 1.0f;
  tf.unitDistance = 0.2f;
  return tf;
}

/// The medium renderers sample `mesh` through (world = origin + spacing * grid).
inline amrdm::DualMeshMedium samplingMedium(const amrdm::DualMesh& mesh,
  const amrdm::TransferFunction& tf)
{
  amrdm::DualMeshMedium m;
  m.mesh = mesh.view();
  m.tf = tf.view();
  m.origin = glm::vec3(mesh.origin);
  m.invSpacing = glm::vec3(1.0 / mesh.finestSpacing);
  return m;
}

/// World bounds of what `mesh` can sample.
inline void meshWorldBounds(const amrdm::DualMesh& mesh, glm::vec3& lo, glm::vec3& hi)
{
  glm::vec3 glo, ghi;
  mesh.gridBounds(glo, ghi);
  lo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * glo;
  hi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * ghi;
}

} // namespace amrdm_test
