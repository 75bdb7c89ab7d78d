// Perspective and parallel cameras generating world rays, following vtkCamera's conventions:
// the view angle is the full vertical angle in degrees, the parallel scale is half the image
// height in world units, and the image aspect (width / height) stretches horizontally.
// A camera can instead be given as a projective ray map (`projective`): the rays of a
// renderer's composite projection, unprojected on the host (window centre, view shear, tiles of
// a large screenshot, a volume's matrix all included). Host/device code.
#pragma once

#include "core/Ray.h"

namespace amrdm
{

struct CameraParams
{
  glm::vec3 position{ 0.0f, 0.0f, 1.0f };   ///< eye point, world units
  glm::vec3 direction{ 0.0f, 0.0f, -1.0f }; ///< view direction (normalised on use)
  glm::vec3 up{ 0.0f, 1.0f, 0.0f };         ///< view up (orthogonalised on use)
  bool parallel = false;                    ///< false = perspective, true = parallel projection
  float viewAngle = 30.0f;                  ///< perspective: vertical full angle, degrees, (0, 180)
  float parallelScale = 1.0f;               ///< parallel: half image height, world units, > 0

  /// When true the fields below define the rays and the ones above are ignored: for normalised
  /// device coordinates (sx, sy) in [-1, 1]^2 of the image, the ray starts at
  /// origin0 + sx * originX + sy * originY (on the near plane) and runs along
  /// direction0 + sx * directionX + sy * directionY (normalised on use). Any projective camera
  /// (perspective or parallel, with window centre, shear or an off-centre tile) composed with an
  /// affine model matrix has rays of this form.
  bool projective = false;
  glm::vec3 origin0{ 0.0f }, originX{ 0.0f }, originY{ 0.0f };
  glm::vec3 direction0{ 0.0f, 0.0f, -1.0f }, directionX{ 0.0f }, directionY{ 0.0f };
  /// Projective cameras: the eye (perspective) or the camera's position (parallel), where every
  /// ray's Ray::tCamera is measured from (dot(origin - anchor, direction)), so that the ray
  /// marcher's lattice does not depend on the near plane: N ranks whose clipping ranges differ
  /// sample each ray where one rank does. (The classic cameras start their rays there.)
  glm::vec3 anchor{ 0.0f };
};

/// Primary ray through image point (px + jitter.x, py + jitter.y) of a width x height image,
/// pixel (0, 0) at the bottom left (VTK's convention); jitter in [0, 1)^2.
AMRDM_HD Ray generateCameraRay(const CameraParams& cam,
  int width,
  int height,
  int px,
  int py,
  const glm::vec2& jitter)
{
  if (cam.projective)
  {
    const float sx = 2.0f * (float(px) + jitter.x) / float(width) - 1.0f;
    const float sy = 2.0f * (float(py) + jitter.y) / float(height) - 1.0f;
    Ray ray;
    ray.o = cam.origin0 + sx * cam.originX + sy * cam.originY;
    ray.d = glm::normalize(cam.direction0 + sx * cam.directionX + sy * cam.directionY);
    ray.tCamera = glm::dot(ray.o - cam.anchor, ray.d);
    return ray;
  }
  const glm::vec3 w = glm::normalize(cam.direction);
  const glm::vec3 u = glm::normalize(glm::cross(w, cam.up)); // image right
  const glm::vec3 v = glm::cross(u, w);                      // image up
  const float aspect = float(width) / float(height);
  // Screen coordinates in [-1, 1] vertically, [-aspect, aspect] horizontally.
  const float sx = (2.0f * (float(px) + jitter.x) / float(width) - 1.0f) * aspect;
  const float sy = 2.0f * (float(py) + jitter.y) / float(height) - 1.0f;
  Ray ray;
  if (cam.parallel)
  {
    ray.o = cam.position + cam.parallelScale * (sx * u + sy * v);
    ray.d = w;
  }
  else
  {
    const float tanHalf = std::tan(glm::radians(0.5f * cam.viewAngle));
    ray.o = cam.position;
    ray.d = glm::normalize(w + tanHalf * (sx * u + sy * v));
  }
  return ray;
}

} // namespace amrdm
