// The default view of the front-ends that frame a data set themselves (amrdm-render, the
// benchmarks' scenes): the eye on a sphere around the focal point at an azimuth and elevation
// (z up), far enough for the view angle to take in the bounds, and a directional key light above
// and to the left of the camera (a light straight from the eye looks flat), and the transfer
// function's unit distance. The mapper uses VTK's camera, light kit and the volume property's
// unit distance instead. Header only.
#pragma once

#include "core/Camera.h"
#include "render/RenderParams.h"

#include <glm/glm.hpp>

#include <cmath>

namespace amrdm_app
{
constexpr double kDefaultAzimuth = 35.0;   ///< degrees, from -y towards +x
constexpr double kDefaultElevation = 25.0; ///< degrees above the xy plane
constexpr float kKeyLightIrradiance = 4.0f;

/// The eye that frames a sphere of `radius` around `focal` with a view angle of `viewAngle`
/// degrees, seen from `azimuth`, `elevation` (degrees), `zoom` times closer.
inline glm::dvec3 DefaultEye(const glm::dvec3& focal,
  double radius,
  double azimuth,
  double elevation,
  double viewAngle,
  double zoom = 1.0)
{
  const double az = glm::radians(azimuth), el = glm::radians(elevation);
  const glm::dvec3 toEye(std::cos(el) * std::sin(az), -std::cos(el) * std::cos(az), std::sin(el));
  const double distance = radius / std::sin(glm::radians(0.5 * viewAngle)) / zoom;
  return focal + distance * toEye;
}

/// The transfer function's unit distance: a quarter of the framed bounds' half-diagonal.
inline double DefaultUnitDistance(double radius)
{
  return 0.25 * radius;
}

/// A directional key light of irradiance kKeyLightIrradiance above and to the left of `cam`.
inline amrdm::Light DefaultKeyLight(const amrdm::CameraParams& cam)
{
  const glm::vec3 w = cam.direction, u = glm::normalize(glm::cross(w, cam.up));
  const glm::vec3 v = glm::cross(u, w);
  amrdm::Light key;
  key.type = amrdm::LightType::Directional;
  key.direction = glm::normalize(-w + 0.6f * v - 0.4f * u);
  key.intensity = kKeyLightIrradiance;
  return key;
}
} // namespace amrdm_app
