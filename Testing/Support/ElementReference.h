// The reference elements the element tests compare our float kernels against, written
// independently of the kernels: unit corners per kind, the signed distance of pcoords to the
// reference element's boundary, float rounding that GCC cannot fold away, and one dispatch to the
// kernels' per-kind evaluation. Shared by Testing/Kernels/mesh/TestElements*.cxx (double-precision
// shape functions) and Testing/Mapper/TestElementOracle.cxx (VTK's cells).
#pragma once

#include "mesh/ElementList.h"
#include "mesh/Elements.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <vector>

namespace amrdm_test
{
static_assert(amrdm::kElementKindCount == 4,
  "Testing/Support/ElementReference.h: write the reference of the new element kind of "
  "mesh/ElementList.h (unitCorners, referenceDistance, evaluateElement), then its oracle in "
  "TestElements*.cxx and TestElementOracle.cxx");

constexpr int kTet = int(amrdm::ElementKind::Tet), kPyramid = int(amrdm::ElementKind::Pyramid),
              kWedge = int(amrdm::ElementKind::Wedge), kHex = int(amrdm::ElementKind::Hex);

/// Rounds to float through volatile stores. GCC 12 at -O2 folds the vectorised round trip
/// dvec3(vec3(d)) back into d for some lanes, which would make the double "truth" refer to a
/// point the kernels never see.
inline glm::vec3 toFloat(const glm::dvec3& d)
{
  volatile float x = static_cast<float>(d.x), y = static_cast<float>(d.y),
                 z = static_cast<float>(d.z);
  return glm::vec3(x, y, z);
}

/// The unit cell of a kind, VTK corner order; its corners are also their pcoords, except for
/// the pyramid apex (pcoords (0, 0, 1), here at (0.5, 0.5, 1)).
inline std::vector<glm::dvec3> unitCorners(int kind)
{
  switch (kind)
  {
    case kTet:
      return { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    case kPyramid:
      return { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 } };
    case kWedge:
      return { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } };
    default:
    {
      // Counter-clockwise bottom face (z = 0), then the top face above it.
      std::vector<glm::dvec3> x;
      for (int i = 0; i < 8; ++i)
        x.emplace_back((i % 4 == 1 || i % 4 == 2) ? 1 : 0, (i % 4 >= 2) ? 1 : 0, i >= 4 ? 1 : 0);
      return x;
    }
  }
}

/// Signed parametric distance of pcoords c to the reference element's boundary (positive
/// inside). For the pyramid, r and s are scaled by 1 - t: the side faces converge at the apex,
/// and an unscaled pcoord margin would vanish physically there.
inline double referenceDistance(int kind, const glm::dvec3& c)
{
  const double d = std::min({ c.x, c.y, c.z });
  switch (kind)
  {
    case kTet:
      return std::min(d, 1 - c.x - c.y - c.z);
    case kWedge:
      return std::min({ d, 1 - c.x - c.y, 1 - c.z });
    case kPyramid:
    {
      const double h = 1 - c.z;
      return std::min({ c.z, h, c.x * h, c.y * h, (1 - c.x) * h, (1 - c.y) * h });
    }
    default:
      return std::min({ d, 1 - c.x, 1 - c.y, 1 - c.z });
  }
}

/// The kernels' evaluation of element `kind` (corners v, float point p): the tet's closed form
/// as an ElementSample, the other kinds' evaluate* functions.
inline amrdm::ElementSample evaluateElement(int kind,
  const glm::vec4* v,
  const glm::vec3& p,
  const amrdm::ElementTestParams& prm)
{
  switch (kind)
  {
    case kTet:
    {
      float value = 0.0f;
      const bool in = amrdm::sampleTet(v, p, value);
      return amrdm::ElementSample{ in, true, value, glm::vec3(0.0f), 0 };
    }
    case kPyramid:
      return amrdm::evaluatePyramid(v, p, prm);
    case kWedge:
      return amrdm::evaluateWedge(v, p, prm);
    default:
      return amrdm::evaluateHex(v, p, prm);
  }
}
} // namespace amrdm_test
