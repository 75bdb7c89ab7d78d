// Geometry extremes (kernel only, no VTK; docs/ROBUSTNESS.md "Geometry extremes"): deep
// refinement (20-27 levels of ratio 2, grid coordinates up to 2^29 finest cells), a world origin
// at 1e6 with finest cells of 1e-3 ... 1e-6 (sampling and rendering in the scene frame),
// strongly anisotropic spacing, boxes one or two cells thick, and thousands of tiny boxes. Each
// case: linear reproduction (error <= 1e-5 of the field's range over the sampled region), no
// misses, and every claiming primitive agrees (watertight, single-valued).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <chrono>
#include <cstring>
#include <random>
#include <set>

using namespace amrdm;

namespace
{
/// The tolerance, relative to the field's range over the sampled region.
constexpr double kRelativeTolerance = 1e-5;

/// f(p) = a . (p - c) + b in grid space (finest units); c keeps the values near the sampled
/// region small, so that float cell values do not limit the test.
struct Linear
{
  glm::dvec3 a{ 0.7, -1.3, 0.45 };
  glm::dvec3 c{ 0.0 };
  double b = 3.0;
  double operator()(const glm::dvec3& p) const { return glm::dot(this->a, p - this->c) + this->b; }
  double range(const glm::dvec3& lo, const glm::dvec3& hi) const
  {
    return glm::dot(glm::abs(this->a), hi - lo);
  }
};

void fill(AmrHierarchy& amr, const Linear& f)
{
  for (AmrBlock& block : amr.blocks)
  {
    const double w = static_cast<double>(amr.levelWidth(block.level));
    block.values.resize(static_cast<std::size_t>(block.numCells()));
    std::size_t i = 0;
    for (int z = 0; z < block.dims.z; ++z)
      for (int y = 0; y < block.dims.y; ++y)
        for (int x = 0; x < block.dims.x; ++x)
          block.values[i++] = float(f((glm::dvec3(block.lower + glm::ivec3(x, y, z)) + 0.5) * w));
  }
}

AmrBlock box(int level, glm::ivec3 lower, glm::ivec3 dims)
{
  AmrBlock b;
  b.level = level;
  b.lower = lower;
  b.dims = dims;
  return b;
}

DualMesh build(AmrHierarchy& amr, int threads = 0)
{
  amr.validate();
  amr.finalizeCellStates();
  DualMeshBuildOptions options;
  options.threads = threads;
  return buildDualMesh(amr, options);
}

/// Random grid points in [lo, hi]; every other one snapped on 1-3 axes to a cell-centre plane
/// of one of `widths` (faces, edges and corners of dual cells).
std::vector<glm::dvec3> pointsIn(std::mt19937& rng,
  const glm::dvec3& lo,
  const glm::dvec3& hi,
  std::size_t n,
  const std::vector<double>& widths)
{
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::dvec3> points(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    glm::dvec3 p = lo + glm::dvec3(u(rng), u(rng), u(rng)) * (hi - lo);
    if (i % 2 == 1)
    {
      const double w = widths[rng() % widths.size()];
      for (int d = 0; d < 1 + static_cast<int>(rng() % 3u); ++d)
        p[d] = glm::clamp((std::floor(p[d] / w - 0.5) + 0.5) * w, lo[d], hi[d]);
    }
    points[i] = p;
  }
  return points;
}

struct ProbeResult
{
  long misses = 0;
  double linear = 0.0, spread = 0.0; ///< worst error and worst disagreement, / range
};

/// Samples in double grid space (the host query path) and compares with expect(p); p is a
/// reference into `points`, so expect may look up data kept per point.
template<typename Expect>
ProbeResult probe(const DualMesh& mesh,
  const std::vector<glm::dvec3>& points,
  Expect&& expect,
  double range)
{
  ProbeResult r;
  const DualMeshView view = mesh.view();
  for (const glm::dvec3& p : points)
  {
    float values[16];
    std::uint32_t refs[16];
    const int hits = sampleFieldAllHits(view, p, ElementTestParams{}, values, refs, 16);
    if (hits == 0)
    {
      ++r.misses;
      continue;
    }
    r.linear = std::max(r.linear, std::abs(values[0] - expect(p)) / range);
    for (int h = 1; h < hits; ++h)
      r.spread = std::max(r.spread, std::abs(double(values[h]) - values[0]) / range);
  }
  return r;
}

void checkProbe(const ProbeResult& r, const std::string& what)
{
  MESSAGE(what,
    ": misses ",
    r.misses,
    ", worst linear error / range ",
    r.linear,
    ", worst spread between claims / range ",
    r.spread);
  CHECK_MESSAGE(r.misses == 0, what);
  CHECK_MESSAGE(r.linear <= kRelativeTolerance, what);
  CHECK_MESSAGE(r.spread <= kRelativeTolerance, what);
}

std::int64_t stitching(const DualMesh& m)
{
  return m.counts.totalElements();
}

/// An 8^3 root, then per level an 8^3 box refining the centre 4^3 cells of the previous box:
/// the finest box sits near grid coordinate 4 * 2^(levels-1).
AmrHierarchy nestedChain(int levels)
{
  AmrHierarchy amr;
  amr.ratio.assign(static_cast<std::size_t>(levels), 2);
  amr.ratio[0] = 1;
  glm::ivec3 lower(0);
  amr.blocks.push_back(box(0, lower, glm::ivec3(8)));
  for (int l = 1; l < levels; ++l)
  {
    lower = (lower + 2) * 2;
    amr.blocks.push_back(box(l, lower, glm::ivec3(8)));
  }
  return amr;
}

bool sameMesh(const DualMesh& a, const DualMesh& b)
{
  bool same = a.gridlets.size() == b.gridlets.size() &&
              a.gridletScalars.size() == b.gridletScalars.size() &&
              a.vertices.size() == b.vertices.size() && a.bvh.nodes.size() == b.bvh.nodes.size() &&
              a.bvh.prims == b.bvh.prims;
  same =
    same &&
    std::memcmp(a.gridlets.data(), b.gridlets.data(), a.gridlets.size() * sizeof(GridletHeader)) ==
      0 &&
    std::memcmp(a.gridletScalars.data(),
      b.gridletScalars.data(),
      a.gridletScalars.size() * sizeof(float)) == 0 &&
    std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(ElementVertex)) ==
      0 &&
    std::memcmp(a.bvh.nodes.data(), b.bvh.nodes.data(), a.bvh.nodes.size() * sizeof(BvhNode)) == 0;
  for (int t = 0; t < kElementKindCount; ++t)
    same = same && a.elementIndices[t] == b.elementIndices[t];
  return same;
}
} // namespace

TEST_CASE("deep refinement: 20 to 27 levels of ratio 2, sampled in the finest levels")
{
  for (int levels : { 20, 22, 24, 27 })
  {
    AmrHierarchy amr = nestedChain(levels);
    // Sample the box of level levels-3: the three finest levels and their stitching.
    const AmrBlock region = amr.blocks[static_cast<std::size_t>(levels - 3)];
    const double w = static_cast<double>(amr.levelWidth(levels - 3));
    const glm::dvec3 lo = glm::dvec3(region.lower) * w + w;
    const glm::dvec3 hi = glm::dvec3(region.lower + region.dims) * w - w;
    Linear f;
    f.c = 0.5 * (lo + hi);
    fill(amr, f);
    AmrHierarchy copy = amr;
    const DualMesh mesh = build(amr);
    std::mt19937 rng(static_cast<unsigned>(levels));
    const ProbeResult r =
      probe(mesh, pointsIn(rng, lo, hi, 20000, { 1.0, 2.0, 4.0 }), f, f.range(lo, hi));
    MESSAGE(levels,
      " levels: finest box at grid coordinate ",
      amr.blocks.back().lower.x,
      " (float resolves ",
      std::ldexp(1.0, int(std::log2(double(amr.blocks.back().lower.x))) - 23),
      " there), ",
      mesh.counts.leafCells,
      " leaf cells, ",
      stitching(mesh),
      " stitching elements");
    checkProbe(r, std::to_string(levels) + " levels");
    CHECK(stitching(mesh) > 0);
    if (levels == 24)
    {
      CHECK(sameMesh(mesh, build(copy, 1))); // any thread count, the same mesh
    }
  }
}

TEST_CASE("grid coordinates beyond +-2^30 finest cells are refused with a message")
{
  AmrHierarchy amr = nestedChain(29); // the finest box reaches past 2^30
  fill(amr, Linear{});
  CHECK_THROWS_WITH_AS(
    build(amr), doctest::Contains("within +-2^30 finest cells"), std::invalid_argument);
  AmrHierarchy tooDeep;
  tooDeep.ratio.assign(40, 2);
  tooDeep.ratio[0] = 1;
  tooDeep.blocks.push_back(box(0, glm::ivec3(0), glm::ivec3(2)));
  tooDeep.blocks[0].values.assign(8, 1.0f);
  CHECK_THROWS_WITH_AS(tooDeep.validate(),
    doctest::Contains("total refinement of at most 2^30"),
    std::invalid_argument);
}

namespace
{
/// A three-level synthetic scene with finest spacing h whose world frame starts at `world`.
DualMesh offsetScene(double h, const glm::dvec3& world, bool sceneOrigin)
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = 3;
  opt.rootCells = glm::ivec3(8);
  opt.boxesPerLevel = 3;
  opt.maxBoxCells = 4;
  AmrHierarchy amr = amrdm_test::makeSynthetic(5,
    opt,
    [](const glm::dvec3& p)
    {
      return float(0.2 + 0.03 * p.x + 0.02 * p.y - 0.01 * p.z); // grid units: about 0.2 .. 1.2
    });
  amr.finestSpacing = glm::dvec3(h);
  (sceneOrigin ? amr.sceneOrigin : amr.origin) = world;
  return build(amr);
}

/// 48^2 render with the camera given in world coordinates (double): in the scene frame
/// (mesh.sceneFromWorld, as the VTK mapper converts it) or, for `floatWorld`, as plain floats.
std::vector<float> renderWorld(const DualMesh& mesh,
  const glm::dvec3& eye,
  const glm::dvec3& focal,
  IntegratorType integrator,
  double h,
  bool floatWorld = false)
{
  TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.05f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.3f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.6f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.9f) };
  tf.lo = 0.2f;
  tf.hi = 1.2f;
  tf.unitDistance = float(8.0 * h);
  CpuRenderer r;
  r.setMesh(&mesh);
  r.setTransferFunction(tf);
  RenderParams p;
  p.width = p.height = 48;
  p.integrator = integrator;
  p.samplesPerPass = 8;
  p.camera.position = floatWorld ? glm::vec3(eye) : glm::vec3(mesh.sceneFromWorld(eye));
  p.camera.direction = glm::vec3(glm::normalize(focal - eye));
  p.camera.up = glm::vec3(0.0f, 0.0f, 1.0f);
  p.numLights = 1;
  p.lights[0].direction = glm::normalize(glm::vec3(1.0f, 0.5f, 2.0f));
  p.lights[0].intensity = 2.0f;
  p.ambient = glm::vec3(0.3f);
  r.renderPass(p);
  return r.image();
}

double meanAbsDiff(const std::vector<float>& a, const std::vector<float>& b)
{
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += std::abs(double(a[i]) - double(b[i]));
  return sum / double(a.size());
}
} // namespace

TEST_CASE("world origin at 1e6, finest cells 1e-3 to 1e-6: probes and renders as at the origin")
{
  const glm::dvec3 far(1e6, 1e6, 1e6);
  for (double h : { 1e-3, 1e-4, 1e-5, 1e-6 })
  {
    const DualMesh ref = offsetScene(h, glm::dvec3(0.0), true);
    const DualMesh off = offsetScene(h, far, true);
    // World-space probe: points 1e6 + relative position (double), converted by the mesh.
    std::mt19937 rng(3);
    const glm::dvec3 lo(4.0), hi(28.0); // grid units, one root cell inside
    Linear f;
    f.a = glm::dvec3(0.03, 0.02, -0.01);
    f.b = 0.2;
    for (const DualMesh* m : { &ref, &off })
    {
      const glm::dvec3 base = m == &ref ? glm::dvec3(0.0) : far;
      std::vector<glm::dvec3> world;
      for (const glm::dvec3& g : pointsIn(rng, lo, hi, 5000, { 1.0, 2.0, 4.0 }))
        world.push_back(base + g * h);
      std::vector<glm::dvec3> grid;
      for (const glm::dvec3& x : world)
        grid.push_back(m->gridFromWorld(x));
      // Expected values from the world positions (the probe's grid points come from them).
      const ProbeResult r = probe(
        *m,
        grid,
        [&](const glm::dvec3& g) { return f((world[std::size_t(&g - grid.data())] - base) / h); },
        f.range(lo, hi));
      checkProbe(
        r, "probe, origin " + std::to_string(base.x) + ", finest cell " + std::to_string(h));
    }
    // The kernel renderer, camera converted as the mapper does: the same image at 1e6.
    const glm::dvec3 eye = glm::dvec3(70.0, -40.0, 55.0) * h, focal = glm::dvec3(16.0) * h;
    for (IntegratorType integrator : { IntegratorType::RayMarch, IntegratorType::PathTracer })
    {
      const std::vector<float> a = renderWorld(ref, eye, focal, integrator, h);
      const std::vector<float> b = renderWorld(off, far + eye, far + focal, integrator, h);
      double alpha = 0.0;
      for (std::size_t k = 3; k < a.size(); k += 4)
        alpha += a[k] / (a.size() / 4.0);
      const double diff = meanAbsDiff(a, b);
      MESSAGE("render, finest cell ",
        h,
        ", integrator ",
        int(integrator),
        ": mean abs difference at 1e6 ",
        diff,
        " (mean alpha ",
        alpha,
        ")");
      CHECK(alpha > 0.1);
      CHECK(diff < 1e-3);
      if (integrator == IntegratorType::RayMarch)
      {
        // Sensitivity: the same scene with float world coordinates (no scene origin) is wrong,
        // so the comparison above can fail.
        const DualMesh naive = offsetScene(h, far, false);
        const double wrong =
          meanAbsDiff(a, renderWorld(naive, far + eye, far + focal, integrator, h, true));
        MESSAGE("  without a scene origin (float world coordinates): mean abs difference ", wrong);
        CHECK(wrong > 1e-2);
      }
    }
  }
}

TEST_CASE("strongly anisotropic spacing: linear in world coordinates, watertight")
{
  for (const glm::dvec3 h : { glm::dvec3(1.0, 1e-3, 1e3),
         glm::dvec3(1e3, 1.0, 1e-3),
         glm::dvec3(1e-3, 1e3, 1.0),
         glm::dvec3(1e-4, 1e-4, 1.0) })
  {
    amrdm_test::SyntheticOptions opt;
    opt.levels = 4;
    opt.rootCells = glm::ivec3(8, 7, 6);
    opt.boxesPerLevel = 3;
    Linear world; // in world units: about one unit over the domain per axis
    world.a = glm::dvec3(0.7, -1.3, 0.45) / (glm::dvec3(opt.rootCells) * 8.0 * h);
    AmrHierarchy amr =
      amrdm_test::makeSynthetic(11, opt, [&](const glm::dvec3& g) { return float(world(g * h)); });
    const double w0 = static_cast<double>(amr.levelWidth(0));
    const glm::dvec3 extent = glm::dvec3(opt.rootCells) * w0; // grid units
    amr.finestSpacing = h;
    amr.sceneOrigin = glm::dvec3(-3.0, 5.0, 1e4);
    const DualMesh mesh = build(amr);
    std::mt19937 rng(5);
    std::vector<glm::dvec3> x; // world points
    for (const glm::dvec3& g : pointsIn(rng, glm::dvec3(w0), extent - w0, 20000, { 1.0, 2.0, w0 }))
      x.push_back(amr.sceneOrigin + g * h);
    std::vector<glm::dvec3> grid;
    for (const glm::dvec3& p : x)
      grid.push_back(mesh.gridFromWorld(p));
    const ProbeResult r = probe(
      mesh,
      grid,
      [&](const glm::dvec3& g)
      { return world(x[std::size_t(&g - grid.data())] - amr.sceneOrigin); },
      world.range(glm::dvec3(0.0), extent * h));
    checkProbe(r,
      "spacing (" + std::to_string(h.x) + ", " + std::to_string(h.y) + ", " + std::to_string(h.z) +
        ")");
    CHECK(stitching(mesh) > 0);
  }
}

TEST_CASE("boxes one or two cells thick")
{
  struct Case
  {
    const char* name;
    glm::ivec3 root;
    std::vector<AmrBlock> blocks; ///< beyond level 0 (or all, when rootSlabs)
    int levels;
    bool rootSlabs; ///< level 0 as slabs one cell thick
  };
  const std::vector<Case> cases = {
    { "level-1 slab 2 cells thick", glm::ivec3(8), { box(1, { 4, 4, 6 }, { 8, 8, 2 }) }, 2, false },
    { "the slab as two blocks 1 cell thick",
      glm::ivec3(8),
      { box(1, { 4, 4, 6 }, { 8, 8, 1 }), box(1, { 4, 4, 7 }, { 8, 8, 1 }) },
      2,
      false },
    { "level-1 pencil 2x2 cells", glm::ivec3(8), { box(1, { 2, 6, 6 }, { 12, 2, 2 }) }, 2, false },
    { "nested slabs: 4 cells on level 1, 2 on level 2",
      glm::ivec3(8),
      { box(1, { 4, 4, 6 }, { 8, 8, 4 }), box(2, { 10, 10, 14 }, { 8, 8, 2 }) },
      3,
      false },
    { "level 0 as 8 slabs 1 cell thick",
      glm::ivec3(8),
      { box(1, { 4, 4, 4 }, { 8, 8, 8 }) },
      2,
      true },
    { "a domain 2 cells thick",
      glm::ivec3(8, 8, 2),
      { box(1, { 4, 4, 0 }, { 8, 8, 4 }) },
      2,
      false },
  };
  for (const Case& c : cases)
  {
    AmrHierarchy amr;
    amr.ratio.assign(static_cast<std::size_t>(c.levels), 2);
    amr.ratio[0] = 1;
    if (c.rootSlabs)
      for (int z = 0; z < c.root.z; ++z)
        amr.blocks.push_back(box(0, { 0, 0, z }, { c.root.x, c.root.y, 1 }));
    else
      amr.blocks.push_back(box(0, glm::ivec3(0), c.root));
    amr.blocks.insert(amr.blocks.end(), c.blocks.begin(), c.blocks.end());
    const double w0 = static_cast<double>(amr.levelWidth(0));
    // Probes the hull of the leaf-cell centres, half a root cell inside the domain (the boundary
    // layer beyond it: TestRandomHierarchies, TestBoundaryLayer).
    const glm::dvec3 lo(0.5 * w0), hi = (glm::dvec3(c.root) - 0.5) * w0;
    Linear f;
    fill(amr, f);
    const DualMesh mesh = build(amr);
    std::mt19937 rng(9);
    checkProbe(
      probe(mesh, pointsIn(rng, lo, hi, 20000, { 1.0, 2.0, w0 }), f, f.range(lo, hi)), c.name);
    CHECK_MESSAGE(stitching(mesh) > 0, c.name);
  }
  // A domain one cell thick has one layer of cell centres: no interior dual cells, only the
  // clamped boundary layer (the slab between its two faces, 9 x 9 x 2 boundary cubes, in
  // gridlets of at most 8 a side from one cell below the lower faces: 2 x 2 x 1), which holds the
  // cells' bilinear interpolant constant across the slab and renders.
  AmrHierarchy flat;
  flat.ratio = { 1 };
  flat.blocks = { box(0, glm::ivec3(0), { 8, 8, 1 }) };
  const Linear lin;
  fill(flat, lin);
  const DualMesh slab = build(flat);
  CHECK(slab.counts.gridlets == 2 * 2 * 1);
  CHECK(slab.counts.perfectCubes == 9 * 9 * 2);
  CHECK(stitching(slab) == 0);
  CHECK(slab.counts.leafCells == 64);
  float v = 0.0f;
  CHECK(sampleField(slab.view(), glm::dvec3(4.0, 4.0, 0.9), ElementTestParams{}, v));
  CHECK(v == doctest::Approx(lin(glm::dvec3(4.0, 4.0, 0.5))).epsilon(1e-5));
  const std::vector<float> image =
    renderWorld(slab, { 40.0, -30.0, 20.0 }, { 8.0, 8.0, 1.0 }, IntegratorType::PathTracer, 1.0);
  CHECK(*std::max_element(image.begin(), image.end()) > 0.0f);
}

TEST_CASE("thousands of tiny boxes: 4000 boxes of 2x2x2 cells on level 1")
{
  const glm::ivec3 root(32);
  AmrHierarchy amr;
  amr.ratio = { 1, 2 };
  amr.blocks.push_back(box(0, glm::ivec3(0), root));
  std::mt19937 rng(21);
  std::set<std::tuple<int, int, int>> taken;
  while (taken.size() < 4000)
  {
    const glm::ivec3 c(1 + rng() % 30u, 1 + rng() % 30u, 1 + rng() % 30u);
    if (taken.insert({ c.x, c.y, c.z }).second)
      amr.blocks.push_back(box(1, 2 * c, glm::ivec3(2)));
  }
  Linear f;
  fill(amr, f);
  AmrHierarchy copy = amr;
  const auto start = std::chrono::steady_clock::now();
  const DualMesh mesh = build(amr);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto start1 = std::chrono::steady_clock::now();
  const DualMesh single = build(copy, 1);
  const double seconds1 =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start1).count();
  MESSAGE(taken.size(),
    " tiny boxes: ",
    mesh.counts.leafCells,
    " leaf cells, ",
    mesh.counts.gridlets,
    " gridlets, ",
    stitching(mesh),
    " stitching elements, ",
    mesh.memoryReport().bytesPerLeafCell(),
    " B/leaf cell; built in ",
    seconds,
    " s (all threads), ",
    seconds1,
    " s (1 thread)");
  CHECK(sameMesh(mesh, single));
  const glm::dvec3 lo(2.0), hi = glm::dvec3(root) * 2.0 - 2.0;
  std::mt19937 prng(4);
  checkProbe(probe(mesh, pointsIn(prng, lo, hi, 50000, { 1.0, 2.0 }), f, f.range(lo, hi)),
    "4000 tiny boxes");
  CHECK(stitching(mesh) > 0);
}
