// Lights for next-event estimation: directional and point lights (delta lights, sampled
// explicitly) and a uniform ambient environment (reached by escaping paths). Host/device code.
#pragma once

#include "core/Ray.h"

namespace amrdm
{

/// Light slots in RenderParams (fixed size: the struct is copied to the device as is). Eight, as
/// OpenGL's classic light limit: VTK's and ParaView's five-light vtkLightKit fits whole.
constexpr int kMaxLights = 8;

enum class LightType : int
{
  Directional = 0, ///< parallel light arriving from `direction` (toward-light vector)
  Point = 1        ///< isotropic point light at `position`, 1/d^2 falloff
};

struct Light
{
  LightType type = LightType::Directional;
  glm::vec3 direction{ 0.0f, 0.0f, 1.0f }; ///< directional: unit vector from the scene TO the light
  glm::vec3 position{ 0.0f };              ///< point: world position
  glm::vec3 color{ 1.0f };                 ///< RGB scale, >= 0
  float intensity = 1.0f;                  ///< directional: irradiance; point: intensity (W/sr)
};

/// What a light delivers at a point: direction toward it, distance (kInfinity for directional)
/// and the incident radiance integrated over the light's delta (irradiance).
struct LightSample
{
  glm::vec3 wi{ 0.0f };
  float distance = kInfinity;
  glm::vec3 Li{ 0.0f };
};

AMRDM_HD LightSample sampleLight(const Light& light, const glm::vec3& p)
{
  LightSample s;
  if (light.type == LightType::Directional)
  {
    s.wi = glm::normalize(light.direction);
    s.distance = kInfinity;
    s.Li = light.color * light.intensity;
  }
  else
  {
    const glm::vec3 toLight = light.position - p;
    const float d2 = glm::dot(toLight, toLight);
    s.distance = std::sqrt(d2);
    s.wi = d2 > 0.0f ? toLight / s.distance : glm::vec3(0.0f, 0.0f, 1.0f);
    s.Li = d2 > 0.0f ? light.color * (light.intensity / d2) : glm::vec3(0.0f);
  }
  return s;
}

} // namespace amrdm
