// Transfer function: an RGBA table over a scalar domain [lo, hi], linearly interpolated between
// entries and clamped outside the domain (with logScale, the table is over log10 of the value:
// lo and hi are log10 of the domain and values <= 0 take entry 0), plus the unit distance that
// turns table opacity into extinction (vtkVolumeProperty's ScalarOpacityUnitDistance, in world
// units). Host/device code; the host struct owns the table, TransferFunctionView is what kernels
// read.
#pragma once

#include "core/HostDevice.h"

#include <cmath>
#include <vector>

namespace amrdm
{

/// Table opacities are clamped to this value before conversion to extinction, so that
/// sigma_t = -ln(1 - alpha) / unitDistance stays finite (at most ~9.2 / unitDistance).
constexpr float kMaxTableOpacity = 0.9999f;

struct TransferFunctionView
{
  const glm::vec4* table =
    nullptr;                  ///< N entries: RGB = scattering albedo (and colour), A = opacity
  int size = 0;               ///< N >= 1
  float lo = 0.0f, hi = 1.0f; ///< scalar domain mapped onto entries 0 .. N-1
  float unitDistance = 1.0f;  ///< world distance over which opacity A is reached (> 0)
  bool logScale = false;      ///< entries are evenly spaced in log10(value) over [lo, hi]
};

/// Extinction (world units^-1) of table opacity `alpha`.
AMRDM_HD float opacityToExtinction(float alpha, float unitDistance)
{
  const float a = glm::clamp(alpha, 0.0f, kMaxTableOpacity);
  return -std::log(1.0f - a) / unitDistance;
}

/// Continuous table coordinate of value v in [0, N-1] (clamped; NaN maps to 0). Monotonic in v,
/// also with logScale, so value-range majorants stay conservative.
AMRDM_HD AMRDM_FORCE_INLINE float tfCoordinate(const TransferFunctionView& tf, float v)
{
  if (tf.logScale)
  {
    if (!(v > 0.0f))
    {
      return 0.0f; // non-positive and NaN values: below the log domain
    }
    v = std::log10(v);
  }
  const float span = tf.hi - tf.lo;
  float x = span > 0.0f ? (v - tf.lo) / span * float(tf.size - 1) : 0.0f;
  x = x == x ? x : 0.0f;
  return glm::clamp(x, 0.0f, float(tf.size - 1));
}

/// Interpolated RGBA at value v. The opacity is clamped to the interval spanned by the two
/// bracketing entries, so rounding can never lift it above the entries the majorant uses.
AMRDM_HD AMRDM_FORCE_INLINE glm::vec4 tfLookup(const TransferFunctionView& tf, float v)
{
  const float x = tfCoordinate(tf, v);
  const int i0 = glm::min(int(x), tf.size - 1);
  const int i1 = glm::min(i0 + 1, tf.size - 1);
  const float f = x - float(i0);
  const glm::vec4 a = tf.table[i0], b = tf.table[i1];
  glm::vec4 r = a + f * (b - a);
  r.w = glm::clamp(r.w, glm::min(a.w, b.w), glm::max(a.w, b.w));
  return r;
}

/// Extinction at value v.
AMRDM_HD float tfExtinction(const TransferFunctionView& tf, float v)
{
  return opacityToExtinction(tfLookup(tf, v).w, tf.unitDistance);
}

/// Largest extinction the interpolated lookup can return for any value in [a, b]: the maximum
/// over every table entry the interpolation touches (floor of a's coordinate .. ceil of b's).
/// Returns 0 for an empty range (a > b, e.g. a macrocell no primitive overlaps).
AMRDM_HD float tfMaxExtinction(const TransferFunctionView& tf, float a, float b)
{
  if (!(a <= b) || tf.size <= 0)
  {
    return 0.0f;
  }
  const int i0 = int(std::floor(tfCoordinate(tf, a)));
  const int i1 = glm::min(int(std::ceil(tfCoordinate(tf, b))), tf.size - 1);
  float alpha = 0.0f;
  for (int i = i0; i <= i1; ++i)
  {
    alpha = glm::max(alpha, tf.table[i].w);
  }
  return opacityToExtinction(alpha, tf.unitDistance);
}

/// Host-owned transfer function.
struct TransferFunction
{
  std::vector<glm::vec4> table{ glm::vec4(1.0f, 1.0f, 1.0f, 0.0f), glm::vec4(1.0f) };
  float lo = 0.0f, hi = 1.0f;
  float unitDistance = 1.0f;
  bool logScale = false; ///< see TransferFunctionView::logScale

  TransferFunctionView view() const
  {
    TransferFunctionView v;
    v.table = this->table.data();
    v.size = static_cast<int>(this->table.size());
    v.lo = this->lo;
    v.hi = this->hi;
    v.unitDistance = this->unitDistance;
    v.logScale = this->logScale;
    return v;
  }
};

} // namespace amrdm
