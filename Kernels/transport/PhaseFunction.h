// Henyey-Greenstein phase function. Directions are propagation directions: `dIn` is the
// direction the ray travelled before the scattering event, `dOut` after it, and
// cos(theta) = dot(dIn, dOut); g > 0 scatters forward. Host/device code.
#pragma once

#include "core/HostDevice.h"

#include <cmath>

namespace amrdm
{

constexpr float kInvFourPi = 0.07957747154594767f; ///< 1 / (4 pi)
constexpr float kTwoPi = 6.283185307179586f;
/// Below this |g| the phase function is sampled as isotropic (the HG inversion divides by g).
constexpr float kIsotropicG = 1e-3f;
/// Anisotropy is clamped to [-kMaxG, kMaxG]; at |g| = 1 the lobe is a delta.
constexpr float kMaxG = 0.99f;

/// Density over the sphere (sr^-1): (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^(3/2)).
AMRDM_HD float hgPhase(float g, float cosTheta)
{
  g = glm::clamp(g, -kMaxG, kMaxG);
  const float denom = 1.0f + g * g - 2.0f * g * cosTheta;
  return kInvFourPi * (1.0f - g * g) / (denom * std::sqrt(glm::max(denom, 0.0f)));
}

/// Orthonormal basis around unit n (Duff et al. 2017, "Building an orthonormal basis, revisited").
AMRDM_HD void orthonormalBasis(const glm::vec3& n, glm::vec3& b1, glm::vec3& b2)
{
  const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  b1 = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  b2 = glm::vec3(b, sign + n.y * n.y * a, -n.y);
}

/// Samples dOut around dIn with density hgPhase(g, dot(dIn, dOut)) from u in [0, 1)^2.
/// Returns dOut; `pdf` receives its density (equal to the phase value).
AMRDM_HD glm::vec3 hgSample(float g, const glm::vec3& dIn, const glm::vec2& u, float& pdf)
{
  g = glm::clamp(g, -kMaxG, kMaxG);
  float cosTheta;
  if (std::fabs(g) < kIsotropicG)
  {
    cosTheta = 1.0f - 2.0f * u.x;
  }
  else
  {
    const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u.x);
    cosTheta = (1.0f + g * g - s * s) / (2.0f * g);
  }
  cosTheta = glm::clamp(cosTheta, -1.0f, 1.0f);
  const float sinTheta = std::sqrt(glm::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float phi = kTwoPi * u.y;
  glm::vec3 b1, b2;
  orthonormalBasis(dIn, b1, b2);
  pdf = hgPhase(g, cosTheta);
  return glm::normalize(
    sinTheta * std::cos(phi) * b1 + sinTheta * std::sin(phi) * b2 + cosTheta * dIn);
}

} // namespace amrdm
