// World-space rays and the ray/box clip every integrator starts with. Host/device code.
#pragma once

#include "core/HostDevice.h"

#include <limits>

namespace amrdm
{

/// Stands for "no bound" in ray intervals and DDA crossings.
constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Ray
{
  glm::vec3 o{ 0.0f };             ///< origin, world units
  glm::vec3 d{ 0.0f, 0.0f, 1.0f }; ///< direction, unit length
  /// Distance along `d` from the camera's anchor (its eye, CameraParams::anchor) to `o`: 0 for
  /// a ray from the eye, more once the origin was moved forward (the near plane, a clipping
  /// plane, a data-parallel region's box). The ray marcher anchors its sample lattice there, so
  /// the pieces of one camera ray that several regions march sample where the whole ray does.
  float tCamera = 0.0f;
  AMRDM_HD glm::vec3 at(float t) const { return this->o + t * this->d; }
};

/// Clips [t0, t1] to the box [lo, hi]. False when the clipped interval is empty. Axis-parallel
/// rays are handled without dividing by zero.
AMRDM_HD bool clipRayToBox(const Ray& ray,
  const glm::vec3& lo,
  const glm::vec3& hi,
  float& t0,
  float& t1)
{
  for (int a = 0; a < 3; ++a)
  {
    if (ray.d[a] == 0.0f)
    {
      if (ray.o[a] < lo[a] || ray.o[a] > hi[a])
      {
        return false;
      }
      continue;
    }
    const float inv = 1.0f / ray.d[a];
    float tn = (lo[a] - ray.o[a]) * inv;
    float tf = (hi[a] - ray.o[a]) * inv;
    if (tn > tf)
    {
      const float s = tn;
      tn = tf;
      tf = s;
    }
    t0 = tn > t0 ? tn : t0;
    t1 = tf < t1 ? tf : t1;
  }
  return t0 < t1;
}

} // namespace amrdm
