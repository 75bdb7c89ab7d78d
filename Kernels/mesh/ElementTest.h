// How stitching elements (pyramids, wedges, hexes) decide "inside" and interpolate.
// The choice is made at run time; see docs/ARCHITECTURE.md ("Point sampling").
#pragma once

#include "core/ParameterTable.h"

namespace amrdm
{

/// Bilinear: the exact dual-mesh interpolant. Faces are bilinear patches and the iso-parametric
///   map is inverted by Newton iteration (the paper's choice, after OpenVKL).
/// PlanarFaces: faces are replaced by planes and parametric coordinates come from distance
///   ratios between opposite faces. No iteration; exact only for planar-faced elements.
enum class ElementTest : int
{
  Bilinear = 0,
  PlanarFaces = 1
};

/// Parameters of the element test. One copy is passed by value into every sampling call.
struct ElementTestParams
{
  /// Which test; default Bilinear.
  ElementTest test = ElementTest::Bilinear;
  /// Newton iterations for pyramids, wedges and hexes, 1..64; default 10 (the paper's value).
  int maxNewtonIterations = int(param::MaxNewtonIterations.defaultValue);
};

} // namespace amrdm
