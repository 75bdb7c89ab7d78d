// Majorant grid and DDA (kernel only, no VTK): the transfer-function maximum is conservative for
// the interpolated lookup; on synthetic dual meshes (anisotropic world transform) no sampled
// extinction exceeds its macrocell majorant, neither at random points nor at random points of
// DDA segments; a transfer-function change recomputes majorants only; DDA segments tile
// [tmin, tmax] exactly.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "mesh/DualMeshBuilder.h"
#include "sampling/Media.h"
#include "accel/MajorantGrid.h"
#include "accel/MajorantIterator.h"
#include "SyntheticAmr.h"

#include <cmath>
#include <random>

using namespace amrdm;

namespace
{
TransferFunction randomTf(std::mt19937& rng, float lo, float hi)
{
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  TransferFunction tf;
  const int n = 2 + static_cast<int>(rng() % 30u);
  tf.table.resize(static_cast<std::size_t>(n));
  for (auto& e : tf.table)
  {
    const float r = u(rng);
    // Mix of transparent, opaque (clamped) and in-between entries.
    e = glm::vec4(u(rng), u(rng), u(rng), r < 0.3f ? 0.0f : (r > 0.9f ? 1.0f : u(rng)));
  }
  // A domain covering part of the data range: values outside are clamped.
  const float span = hi - lo;
  tf.lo = lo + span * 0.3f * u(rng);
  tf.hi = hi - span * 0.3f * u(rng);
  tf.unitDistance = 0.05f + u(rng);
  return tf;
}
} // namespace

TEST_CASE("TF maximum extinction is conservative for the interpolated lookup")
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-2.0f, 3.0f);
  long long checks = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const TransferFunction tf = randomTf(rng, -1.0f, 2.0f);
    const TransferFunctionView v = tf.view();
    float a = u(rng), b = u(rng);
    if (a > b)
      std::swap(a, b);
    const float maj = tfMaxExtinction(v, a, b);
    for (int i = 0; i <= 200; ++i)
    {
      const float x = a + (b - a) * float(i) / 200.0f;
      REQUIRE(tfExtinction(v, x) <= maj);
      ++checks;
    }
    // Table entries hit exactly.
    for (int i = 0; i < v.size; ++i)
    {
      const float x = v.lo + (v.hi - v.lo) * float(i) / float(v.size - 1);
      CHECK(tfExtinction(v, x) <= tfMaxExtinction(v, x, x));
    }
  }
  CHECK(tfMaxExtinction(TransferFunction().view(), 1.0f, 0.0f) == 0.0f); // empty range
  MESSAGE("lookups checked: ", checks);
}

TEST_CASE("no sampled extinction exceeds its macrocell majorant on synthetic dual meshes")
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long long points = 0, nonzero = 0, segmentPoints = 0;
  double tightness = 0.0;
  for (unsigned seed = 1; seed <= 8; ++seed)
  {
    amrdm_test::SyntheticOptions opt;
    opt.levels = 2 + static_cast<int>(seed % 3);
    opt.rootCells = glm::ivec3(6 + static_cast<int>(seed % 3), 5, 7);
    const amrdm_test::Field field = [seed](const glm::dvec3& p)
    {
      return static_cast<float>(std::sin(0.4 * p.x + seed) * std::cos(0.3 * p.y) + 0.05 * p.z +
                                0.3 * std::sin(2.1 * p.x * p.y));
    };
    AmrHierarchy amr = amrdm_test::makeSynthetic(seed, opt, field);
    amr.origin = glm::dvec3(1.5, -2.0, 0.25);
    amr.finestSpacing = glm::dvec3(0.5, 1.25, 2.0); // anisotropic
    amr.validate();
    amr.finalizeCellStates();
    const DualMesh mesh = buildDualMesh(amr);
    const glm::ivec3 resolutions[2] = { glm::ivec3(0), glm::ivec3(7, 5, 3) };
    for (const glm::ivec3& res : resolutions)
    {
      MajorantGrid grid = buildMajorantRanges(mesh, res, 2);
      const TransferFunction tf = randomTf(rng, -1.2f, 1.2f);
      updateMajorants(grid, tf.view());
      // A TF change: ranges untouched, majorants equal to a fresh build.
      const std::vector<glm::vec2> ranges = grid.range;
      const TransferFunction tf2 = randomTf(rng, -1.2f, 1.2f);
      updateMajorants(grid, tf2.view(), 1);
      CHECK(grid.range == ranges);
      MajorantGrid fresh = buildMajorantRanges(mesh, res, 1);
      updateMajorants(fresh, tf2.view());
      CHECK(fresh.range == grid.range); // thread-count independent
      CHECK(fresh.majorant == grid.majorant);

      DualMeshMedium medium;
      medium.mesh = mesh.view();
      medium.tf = tf2.view();
      medium.origin = glm::vec3(mesh.origin);
      medium.invSpacing = glm::vec3(1.0 / mesh.finestSpacing);
      const MajorantGridView gv = grid.view();
      TraceCounters counters;
      // Random points, half of them snapped to macrocell faces.
      for (int i = 0; i < 20000; ++i)
      {
        glm::vec3 p;
        for (int d = 0; d < 3; ++d)
        {
          p[d] = float(gv.lo[d] + u(rng) * (gv.hi[d] - gv.lo[d]));
          if (i % 2 && rng() % 2)
          {
            const float cell = (gv.hi[d] - gv.lo[d]) / float(gv.res[d]);
            p[d] = gv.lo[d] + cell * std::round((p[d] - gv.lo[d]) / cell);
          }
        }
        const float s = medium.sample(p, counters).sigmaT;
        const float m = majorantAt(gv, p);
        REQUIRE_MESSAGE(s <= m, "seed ", seed, " p ", p.x, " ", p.y, " ", p.z);
        ++points;
        if (s > 0.0f)
        {
          ++nonzero;
          tightness += double(s) / double(m);
        }
      }
      // Points of DDA segments (including both ends) against the segment's majorant.
      for (int r = 0; r < 1000; ++r)
      {
        Ray ray;
        ray.o = glm::vec3(
          gv.lo + (gv.hi - gv.lo) * glm::vec3(float(u(rng)), float(u(rng)), float(u(rng))));
        ray.d =
          glm::normalize(glm::vec3(float(u(rng) - 0.5), float(u(rng) - 0.5), float(u(rng) - 0.5)));
        if (r % 10 == 0)
          ray.d = glm::vec3(0.0f, 0.0f, 1.0f); // axis-parallel
        DdaMajorantIterator it(gv, ray, -1e6f, 1e6f);
        MajorantSegment seg;
        while (it.next(seg))
        {
          for (float f : { 0.0f, float(u(rng)), 1.0f })
          {
            const glm::vec3 p = ray.at(seg.t0 + f * (seg.t1 - seg.t0));
            REQUIRE(medium.sample(p, counters).sigmaT <= seg.sigmaMaj);
            ++segmentPoints;
          }
        }
      }
    }
  }
  MESSAGE("points: ",
    points,
    " (",
    nonzero,
    " with sigma_t > 0, mean sigma_t / majorant ",
    tightness / double(std::max(1LL, nonzero)),
    "), DDA segment points: ",
    segmentPoints);
  CHECK(points + segmentPoints >= 100000);
  CHECK(nonzero > 1000);
}

TEST_CASE("macrocell cell widths bound the finest primitive in each macrocell")
{
  // For every sample point, the primitive claiming it is no finer than its macrocell's
  // cellWidth says; empty macrocells are +inf; a one-level mesh gives that level's width
  // everywhere; the result does not depend on the thread count.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long long checked = 0, coarser = 0;
  for (int levels : { 1, 2, 3, 4 })
  {
    amrdm_test::SyntheticOptions opt;
    opt.levels = levels;
    opt.rootCells = glm::ivec3(7, 6, 5);
    AmrHierarchy amr = amrdm_test::makeSynthetic(
      unsigned(levels), opt, [](const glm::dvec3& p) { return float(p.x + 0.5 * p.y); });
    amr.finestSpacing = glm::dvec3(0.5, 1.25, 2.0); // anisotropic: widths use the smallest
    amr.validate();
    amr.finalizeCellStates();
    const DualMesh mesh = buildDualMesh(amr);
    const MajorantGrid grid = buildMajorantRanges(mesh, glm::ivec3(9, 7, 5), 2);
    CHECK(buildMajorantRanges(mesh, glm::ivec3(9, 7, 5), 1).cellWidth == grid.cellWidth);
    REQUIRE(grid.cellWidth.size() == grid.range.size());
    const float finest = float(mesh.levelWidth.back() * 0.5);
    for (std::size_t i = 0; i < grid.range.size(); ++i)
    {
      if (grid.range[i].x > grid.range[i].y)
        CHECK(std::isinf(grid.cellWidth[i])); // no primitive
      else if (levels == 1)
        CHECK(grid.cellWidth[i] == finest);
      else
        CHECK(grid.cellWidth[i] >= finest);
    }
    DualMeshMedium medium;
    medium.mesh = mesh.view();
    medium.origin = glm::vec3(mesh.origin);
    medium.invSpacing = glm::vec3(1.0 / mesh.finestSpacing);
    const MajorantGridView gv = grid.view();
    for (int n = 0; n < 20000; ++n)
    {
      glm::vec3 p;
      for (int d = 0; d < 3; ++d)
        p[d] = float(gv.lo[d] + u(rng) * (gv.hi[d] - gv.lo[d]));
      TraceCounters counters;
      float v = 0.0f;
      if (!medium.value(p, v, counters))
        continue;
      const std::uint32_t ref = counters.lastPrimitive;
      double width = 0.0;
      if (primType(ref) == PrimGridlet)
        width = mesh.levelWidth[std::size_t(mesh.gridlets[primIndex(ref)].level)];
      else
      {
        // An element: its smallest box extent (it spans two levels; at least the finer width);
        // a boundary-layer element's extent to a domain face is half a cell: it counts twice.
        const int t = primElementKind(primType(ref)), nc = elementCorners(t);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (int c = 0; c < nc; ++c)
        {
          const ElementVertex& ev =
            mesh.vertices[mesh.elementIndices[t][std::size_t(primIndex(ref)) * nc + c]];
          lo = glm::min(lo, 0.5 * glm::dvec3(ev.pos2));
          hi = glm::max(hi, 0.5 * glm::dvec3(ev.pos2));
        }
        glm::dvec3 e = hi - lo;
        for (int d = 0; d < 3; ++d)
          e[d] *= lo[d] == mesh.domainLower[d] || hi[d] == mesh.domainUpper[d] ? 2.0 : 1.0;
        width = std::min(e.x, std::min(e.y, e.z));
        CHECK(width >= mesh.levelWidth.back());
      }
      const float macro = grid.cellWidth[std::size_t(macrocellIndex(gv, macrocellOf(gv, p)))];
      REQUIRE_MESSAGE(
        float(width * 0.5) >= macro, "levels ", levels, " p ", p.x, " ", p.y, " ", p.z);
      ++checked;
      coarser += float(width * 0.5) > macro;
    }
  }
  MESSAGE("points checked: ",
    checked,
    " (",
    coarser,
    " in a primitive coarser than its macrocell's finest)");
  CHECK(checked > 50000);
  CHECK(coarser > 0);
}

TEST_CASE("DDA segments tile [tmin, tmax] exactly and never step past it")
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> values(1000);
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = float(i);
  long long segments = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    MajorantGridView g;
    g.res = glm::ivec3(1 + rng() % 9u, 1 + rng() % 9u, 1 + rng() % 9u);
    g.lo = glm::vec3(u(rng), u(rng), u(rng)) * 10.0f - 5.0f;
    g.hi = g.lo + glm::vec3(0.1f + u(rng), 0.1f + u(rng) * 5.0f, 0.1f + u(rng) * 20.0f);
    g.majorant = values.data();
    Ray ray;
    ray.o = g.lo + (g.hi - g.lo) * (glm::vec3(u(rng), u(rng), u(rng)) * 3.0f - 1.0f);
    glm::vec3 d(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
    if (trial % 7 == 0)
      d[rng() % 3] = 0.0f; // axis-parallel in one or two axes
    if (trial % 11 == 0)
      d = glm::vec3(0.0f), d[rng() % 3] = 1.0f;
    ray.d = glm::normalize(d);
    const float tmin = u(rng) * 4.0f - 2.0f;
    const float tmax = trial % 3 == 0 ? kInfinity : tmin + u(rng) * 30.0f;
    float c0 = tmin, c1 = tmax;
    const bool hits = clipRayToBox(ray, g.lo, g.hi, c0, c1);
    DdaMajorantIterator it(g, ray, tmin, tmax);
    MajorantSegment seg;
    int n = 0;
    float prev = c0, last = c0;
    while (it.next(seg))
    {
      REQUIRE(hits);
      REQUIRE(seg.t0 == prev); // contiguous
      REQUIRE(seg.t1 >= seg.t0);
      REQUIRE(seg.t1 <= c1);
      // The majorant is that of the macrocell holding the midpoint (away from faces).
      const glm::vec3 mid = ray.at(0.5f * (seg.t0 + seg.t1));
      if (seg.t1 - seg.t0 > 1e-3f)
        CHECK(seg.sigmaMaj == g.majorant[macrocellIndex(g, macrocellOf(g, mid))]);
      prev = last = seg.t1;
      ++n;
      REQUIRE(n <= g.res.x + g.res.y + g.res.z + 3);
    }
    if (hits)
    {
      REQUIRE(n >= 1);
      REQUIRE(last == c1); // ends exactly at the clipped tmax
    }
    segments += n;
  }
  MESSAGE("segments checked: ", segments);
}

TEST_CASE("ratio tracking through a dual mesh: the macrocell grid agrees with one global majorant")
{
  // A non-conservative macrocell majorant would bias the estimate; a global bound cannot.
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(8, 6, 7);
  AmrHierarchy amr = amrdm_test::makeSynthetic(21,
    opt,
    [](const glm::dvec3& p) {
      return static_cast<float>(0.5 + 0.5 * std::sin(0.5 * p.x) * std::cos(0.4 * p.y + 0.3 * p.z));
    });
  amr.origin = glm::dvec3(0.0, 1.0, -3.0);
  amr.finestSpacing = glm::dvec3(0.3, 0.2, 0.25);
  amr.validate();
  amr.finalizeCellStates();
  const DualMesh mesh = buildDualMesh(amr);
  TransferFunction tf;
  tf.table = { glm::vec4(1.0f, 1.0f, 1.0f, 0.0f),
    glm::vec4(1.0f, 1.0f, 1.0f, 0.05f),
    glm::vec4(1.0f, 1.0f, 1.0f, 0.6f),
    glm::vec4(1.0f, 1.0f, 1.0f, 0.2f) };
  tf.unitDistance = 0.5f;
  MajorantGrid grid = buildMajorantRanges(mesh);
  updateMajorants(grid, tf.view());
  float globalMax = 0.0f;
  for (float m : grid.majorant)
    globalMax = std::max(globalMax, m);
  const MajorantGrid global = makeConstantMajorantGrid(grid.lo, grid.hi, 1.5f * globalMax);
  DualMeshMedium medium;
  medium.mesh = mesh.view();
  medium.tf = tf.view();
  medium.origin = glm::vec3(mesh.origin);
  medium.invSpacing = glm::vec3(1.0 / mesh.finestSpacing);
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int r = 0; r < 6; ++r)
  {
    Ray ray;
    ray.o =
      grid.lo + (grid.hi - grid.lo) * glm::vec3(u(rng), u(rng), 0.0f) - glm::vec3(0.0f, 0.0f, 1.0f);
    ray.d = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, 2.0f));
    double s[2] = { 0, 0 }, s2[2] = { 0, 0 };
    constexpr int kN = 20000;
    TraceCounters counters;
    for (int i = 0; i < kN; ++i)
    {
      Rng a(std::uint64_t(i), std::uint64_t(r), 0), b(std::uint64_t(i), std::uint64_t(r), 1);
      const double t0 = estimateTransmittance(
        walkContext(medium, grid.view(), a, 1 << 20, counters), ray, 0.0f, kInfinity);
      const double t1 = estimateTransmittance(
        walkContext(medium, global.view(), b, 1 << 20, counters), ray, 0.0f, kInfinity);
      s[0] += t0, s2[0] += t0 * t0, s[1] += t1, s2[1] += t1 * t1;
    }
    double mean[2], var[2];
    for (int k = 0; k < 2; ++k)
    {
      mean[k] = s[k] / kN;
      var[k] = std::max(0.0, s2[k] / kN - mean[k] * mean[k]) / (kN - 1);
    }
    const double sigma = std::sqrt(var[0] + var[1]);
    MESSAGE("ray ",
      r,
      ": T macrocells ",
      mean[0],
      ", T global majorant ",
      mean[1],
      ", diff ",
      std::fabs(mean[0] - mean[1]) / std::max(sigma, 1e-300),
      " sigma");
    CHECK(std::fabs(mean[0] - mean[1]) <= 3.0 * sigma + 1e-6);
    CHECK(counters.majorantViolations == 0);
  }
}
