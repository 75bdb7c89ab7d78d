// The clamped boundary layer against the closed form: a constant field on a multi-level
// hierarchy whose finer levels reach the domain faces fills the whole domain box, so the ray
// marcher's transmittance down each axis and along diagonals is exp(-sigma * chord of the
// domain box) (kDomainTransmittanceTolerance). Without the layer the chord lost half a boundary
// cell at each face (4-5 % of the opacity on a 20-cell domain). An explicit domain box larger
// than the blocks gets its layer at its own faces only.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "core/Tolerances.h"
#include "mesh/DualMeshBuilder.h"
#include "sampling/Media.h"
#include "transport/Integrators.h"
#include "accel/MajorantGrid.h"
#include "SyntheticAmr.h"

#include <cmath>
#include <random>

using namespace amrdm;

namespace
{
constexpr float kValue = 0.5f;

struct Scene
{
  AmrHierarchy amr;
  DualMesh mesh;
  TransferFunction tf;
  MajorantGrid grid;
  DualMeshMedium medium;
  double sigma = 0.0;

  explicit Scene(AmrHierarchy a)
    : amr(std::move(a))
  {
    this->amr.validate();
    this->amr.finalizeCellStates();
    this->mesh = buildDualMesh(this->amr);
    constexpr float kAlpha = 0.3f;
    this->tf.table.assign(4, glm::vec4(1.0f, 1.0f, 1.0f, kAlpha));
    this->tf.unitDistance = 10.0f;
    this->sigma = -std::log(1.0 - double(kAlpha)) / double(this->tf.unitDistance);
    this->grid = buildMajorantRanges(this->mesh);
    updateMajorants(this->grid, this->tf.view());
    this->medium.mesh = this->mesh.view();
    this->medium.tf = this->tf.view();
    this->medium.origin = glm::vec3(this->mesh.origin);
    this->medium.invSpacing = glm::vec3(1.0 / this->mesh.finestSpacing);
  }

  /// Largest |opacity - (1 - exp(-sigma * chord))| over axis-aligned and diagonal rays through
  /// the domain box; `rays` counts the rays that crossed it.
  double worstError(std::mt19937& rng, int& rays) const
  {
    const GridBox box = this->amr.domainBox();
    const glm::dvec3 lo = this->amr.origin + glm::dvec3(box.lower) * this->amr.finestSpacing;
    const glm::dvec3 hi = this->amr.origin + glm::dvec3(box.upper) * this->amr.finestSpacing;
    std::uniform_real_distribution<double> u(0.02, 0.98);
    RenderParams params;
    params.integrator = IntegratorType::RayMarch;
    params.stepSize = 1e-3f;
    params.samplesPerCell = 2.0f;
    params.earlyTermination = 1.0f;
    double worst = 0.0;
    for (int i = 0; i < 48; ++i)
    {
      const glm::dvec3 target = lo + glm::dvec3(u(rng), u(rng), u(rng)) * (hi - lo);
      glm::dvec3 dir(0.0);
      if (i < 24)
        dir[i % 3] = (i / 3) % 2 ? -1.0 : 1.0; // down each axis, both ways
      else
        dir = glm::normalize(
          glm::dvec3(i % 2 ? 1.0 : -1.0, (i / 2) % 2 ? 1.0 : -1.0, (i / 4) % 2 ? 1.0 : -1.0));
      // Chord of the domain box (slabs, in double).
      double t0 = -1e30, t1 = 1e30;
      for (int d = 0; d < 3; ++d)
      {
        if (dir[d] == 0.0)
          continue;
        const double a = (lo[d] - target[d]) / dir[d], b = (hi[d] - target[d]) / dir[d];
        t0 = std::max(t0, std::min(a, b));
        t1 = std::min(t1, std::max(a, b));
      }
      const double back = 1.0 + glm::length(hi - lo);
      Ray ray;
      ray.o = glm::vec3(target - back * dir);
      ray.d = glm::vec3(dir);
      TraceCounters counters;
      const SampleResult r =
        rayMarch(this->medium, this->grid.view(), params, ray, kInfinity, float(u(rng)), counters);
      const double exact = 1.0 - std::exp(-this->sigma * (t1 - t0));
      worst = std::max(worst, std::abs(double(r.alpha) - exact));
      ++rays;
    }
    return worst;
  }
};

} // namespace

TEST_CASE("a constant field fills the domain box: transmittance is exp(-sigma * chord)")
{
  std::mt19937 rng(5);
  double worst = 0.0;
  int rays = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    amrdm_test::SyntheticOptions opt;
    opt.levels = 3;
    opt.rootCells = glm::ivec3(20, 14, 10);
    opt.boxesPerLevel = 4;
    opt.maxBoxCells = 6;
    AmrHierarchy amr =
      amrdm_test::makeSynthetic(seed, opt, [](const glm::dvec3&) { return kValue; });
    amr.origin = glm::dvec3(1.0, -2.0, 0.5);
    amr.finestSpacing = glm::dvec3(0.3, 0.2, 0.25);
    const Scene scene(std::move(amr));
    REQUIRE(scene.amr.numLevels() >= 2);
    // The mesh reaches the domain box exactly (in grid space), no further.
    glm::vec3 glo, ghi;
    scene.mesh.gridBounds(glo, ghi);
    const GridBox box = scene.amr.domainBox();
    CHECK(glo == glm::vec3(box.lower));
    CHECK(ghi == glm::vec3(box.upper));
    worst = std::max(worst, scene.worstError(rng, rays));
  }
  MESSAGE(rays, " rays: worst |opacity - (1 - exp(-sigma chord))| ", worst);
  CHECK(worst <= kDomainTransmittanceTolerance);
}

TEST_CASE("faces of an explicit domain box get the layer; faces inside it do not")
{
  // One block of 6^3 cells in a domain box that extends 2 cells beyond it in +x only.
  AmrHierarchy amr;
  amr.ratio = { 1 };
  AmrBlock block;
  block.dims = glm::ivec3(6);
  block.values.assign(216, kValue);
  amr.blocks.push_back(block);
  amr.domain.lower = glm::ivec3(0);
  amr.domain.upper = glm::ivec3(8, 6, 6);
  amr.finalizeCellStates();
  const DualMesh mesh = buildDualMesh(amr);
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  CHECK(lo == glm::vec3(0.0f));
  CHECK(hi == glm::vec3(5.5f, 6.0f, 6.0f)); // +x ends at the last cell centre: not a domain face
  const DualMeshView view = mesh.view();
  float v = 0.0f;
  CHECK(sampleField(view, glm::vec3(0.0f, 0.1f, 5.9f), ElementTestParams{}, v));
  CHECK(v == doctest::Approx(kValue));
  CHECK_FALSE(sampleField(view, glm::vec3(5.8f, 3.0f, 3.0f), ElementTestParams{}, v));

  // Outside the domain, or off level-0 cell faces: refused with a message.
  auto refused = [](AmrHierarchy h, const char* fragment)
  {
    try
    {
      buildDualMesh(h);
      FAIL("no error for: ", fragment);
    }
    catch (const std::invalid_argument& e)
    {
      MESSAGE(std::string(e.what()));
      CHECK(std::string(e.what()).find(fragment) != std::string::npos);
    }
  };
  AmrHierarchy small = amr;
  small.domain.upper = glm::ivec3(5, 6, 6);
  refused(small, "outside the domain box");
  AmrHierarchy twoLevels = amr;
  twoLevels.ratio = { 1, 2 };
  twoLevels.domain.upper = glm::ivec3(17, 12, 12);
  for (AmrBlock& b : twoLevels.blocks)
    b.state.clear();
  twoLevels.finalizeCellStates();
  refused(twoLevels, "level-0 cell faces");
}
