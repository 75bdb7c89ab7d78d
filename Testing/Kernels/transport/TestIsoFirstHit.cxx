// The exact isosurface search returns the FIRST crossing of the interpolant along a ray, also
// where the crossing lies on (or within float rounding of) a face between two primitives or two
// dual cells (transport/Isosurface.h, IsoPrimitives.h, IsoRoots.h). There the two sides'
// cubics are evaluated separately, and their rounding can put the face on the far side of the
// surface for both: neither side then sees a sign change and the search returns a later
// crossing, or none. On 3-level synthetic hierarchies with fields whose surfaces are known:
//  - a linear field whose surface passes exactly through a point of a dual-cell face (of every
//    level, inside gridlets, at gridlet boundaries and next to stitching elements): rays
//    through the point hit it there;
//  - f = z with iso values within 0.005 of 10 (a level-0 cell-centre plane): every camera ray
//    of the embedded-isosurface test scene hits the plane;
//  - firstCubicRoot on a cubic with a sign change at the interval's end, and with two close
//    roots inside it.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "ThreeLevelScene.h"

#include <cmath>
#include <random>
#include <string>

using namespace amrdm;
using amrdm_test::insideHullXY;
using amrdm_test::kHullHi;
using amrdm_test::kHullLo;
using amrdm_test::makeThreeLevelMesh;
using amrdm_test::randomDir;
using Scene = amrdm_test::MediumScene;

namespace
{

TransferFunction rampTf(float lo, float hi)
{
  TransferFunction tf;
  tf.lo = lo;
  tf.hi = hi;
  tf.table.assign(256, glm::vec4(1.0f));
  return tf;
}

/// Rays traced against a known first crossing t*: how many, how many found none, and how many
/// found another one (|t - t*| > 1e-3).
struct FirstHitTally
{
  int rays = 0, missed = 0, wrong = 0;
  void trace(const Scene& s, const Ray& ray, float iso, double tStar)
  {
    ++rays;
    const IsoHit hit = s.first(ray, iso);
    if (!hit.hit())
      ++missed;
    else
      wrong += std::fabs(hit.t - tStar) > 1e-3;
  }
  /// Every ray hit at t*; more than `minRays` were traced.
  void check(const char* what, int minRays) const
  {
    MESSAGE(rays, " ", std::string(what), ": ", missed, " missed, ", wrong, " off by > 1e-3");
    CHECK(rays > minRays);
    CHECK(missed == 0);
    CHECK(wrong == 0);
  }
};

} // namespace

TEST_CASE("firstCubicRoot: a sign change at the interval's end, two close roots inside")
{
  // (s - 1)(s - 2)(s - 3) on [0, 1]: the root is the end itself.
  const float c1[4] = { -6.0f, 11.0f, -6.0f, 1.0f };
  float root = -1.0f;
  REQUIRE(firstCubicRoot(c1, 1.0f, root));
  CHECK(root == doctest::Approx(1.0f).epsilon(1e-6));
  // (s - 0.5)(s - 0.51)(s - 3): two crossings 0.01 apart (the cubic dips 6e-5 below 0 between
  // them, far above float rounding), the first one first.
  const double r[3] = { 0.5, 0.51, 3.0 };
  const float c2[4] = { float(-r[0] * r[1] * r[2]),
    float(r[0] * r[1] + r[0] * r[2] + r[1] * r[2]),
    float(-(r[0] + r[1] + r[2])),
    1.0f };
  REQUIRE(firstCubicRoot(c2, 1.0f, root));
  CHECK(std::fabs(root - 0.5f) < 1e-5f);
}

TEST_CASE("a linear field's surface through a dual-cell face point is hit there")
{
  // f = a . p; a point q on a dual-cell face of level l (a plane of level-l cell centres,
  // (i + 1/2) w_l on one axis), iso = f(q): rays through q cross the surface at q, on the face
  // shared by two dual cells (or a dual cell and a stitching element, or two gridlets).
  const glm::dvec3 a(1.0 / 48.0, 0.7 / 48.0, 0.45 / 48.0);
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& p) { return float(glm::dot(a, p)); });
  Scene s(mesh, rampTf(0.0f, 2.0f));
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  FirstHitTally tally;
  for (int i = 0; i < 40000; ++i)
  {
    const int level = int(rng() % 3), axis = int(rng() % 3);
    const float w = float(4 >> level);
    glm::vec3 q = kHullLo + 1.0f + (kHullHi - kHullLo - 2.0f) * glm::vec3(u(rng), u(rng), u(rng));
    q[axis] = (std::floor(q[axis] / w - 0.5f) + 0.5f) * w;
    const glm::vec3 d = randomDir(rng);
    const float back = 3.0f + 10.0f * u(rng);
    Ray ray;
    ray.o = q - back * d;
    ray.d = d;
    const float iso = float(glm::dot(a, glm::dvec3(q)));
    const double slope = glm::dot(a, glm::dvec3(d));
    if (std::fabs(slope) < 0.1 * glm::length(a))
      continue; // near-grazing: the surface position along the ray is ill-conditioned
    const double tStar = (double(iso) - glm::dot(a, glm::dvec3(ray.o))) / slope;
    float t0 = 0.0f, t1 = kInfinity;
    if (!clipRayToBox(ray, kHullLo, kHullHi, t0, t1) || !(tStar > t0 + 0.5 && tStar < t1 - 0.5))
      continue;
    tally.trace(s, ray, iso, tStar);
  }
  tally.check("rays through face points", 20000);
}

TEST_CASE("f = z, iso within 0.005 of the level-0 centre plane z = 10: every camera ray hits")
{
  const DualMesh mesh = makeThreeLevelMesh([](const glm::dvec3& q) { return float(q.z); });
  Scene s(mesh, rampTf(0.0f, 40.0f));
  CameraParams camera;
  camera.position = glm::vec3(24.0f, -14.0f, 44.0f);
  camera.direction = glm::vec3(24.0f, 20.0f, 8.0f) - camera.position;
  camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  camera.viewAngle = 50.0f;
  const int width = 96, height = 80;
  FirstHitTally tally;
  for (const float iso : { 9.995f, 9.999f, 9.9999f, 10.0f, 10.0001f, 10.001f, 10.004f, 10.005f })
    for (int py = 0; py < height; ++py)
      for (int px = 0; px < width; ++px)
      {
        const Ray r = generateCameraRay(camera, width, height, px, py, glm::vec2(0.5f));
        const double tStar = (double(iso) - r.o.z) / r.d.z;
        const glm::dvec3 q = glm::dvec3(r.o) + tStar * glm::dvec3(r.d);
        if (!insideHullXY(q))
          continue;
        tally.trace(s, r, iso, tStar);
      }
  tally.check("camera rays", 4000);
}

TEST_CASE("axis-aligned rays lying exactly in dual-cell face planes hit the surface")
{
  // A parallel camera looking along an axis puts rows of rays exactly in the planes of cell
  // centres, i.e. on the faces shared by two gridlets, two dual cells or two BVH boxes: a line
  // in a box's face plane is inside the (closed) box, on both sides.
  const glm::dvec3 a(1.0 / 48.0, 0.7 / 48.0, 0.45 / 48.0);
  const DualMesh mesh =
    makeThreeLevelMesh([&](const glm::dvec3& p) { return float(glm::dot(a, p)); });
  Scene s(mesh, rampTf(0.0f, 2.0f));
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  FirstHitTally tally;
  for (int i = 0; i < 6000; ++i)
  {
    const int axis = int(rng() % 3), level = int(rng() % 3);
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const float w = float(4 >> level);
    glm::vec3 o = kHullLo + 1.0f + (kHullHi - kHullLo - 2.0f) * glm::vec3(u(rng), u(rng), u(rng));
    o[a1] = (std::floor(o[a1] / w - 0.5f) + 0.5f) * w; // in a face plane of level `level`
    if (i % 2)
      o[a2] = (std::floor(o[a2] / w - 0.5f) + 0.5f) * w; // on an edge of two such planes
    glm::vec3 d(0.0f);
    d[axis] = i % 4 < 2 ? 1.0f : -1.0f;
    o[axis] = d[axis] > 0.0f ? kHullLo[axis] : kHullHi[axis];
    Ray ray;
    ray.o = o;
    ray.d = d;
    const float T = 2.0f + (kHullHi[axis] - kHullLo[axis] - 4.0f) * u(rng);
    const float iso = float(glm::dot(a, glm::dvec3(ray.at(T))));
    const double tStar =
      (double(iso) - glm::dot(a, glm::dvec3(ray.o))) / glm::dot(a, glm::dvec3(ray.d));
    tally.trace(s, ray, iso, tStar);
  }
  tally.check("axis-aligned rays in face planes", 0);
}
