// Property test over many random, properly nested hierarchies (levels 1..6, ratio 2, touching
// and nested boxes): linear reproduction and watertightness (no misses, every claiming
// primitive agrees) at random and lattice-aligned points; and the clamped boundary layer (the
// half cells between the cell centres' hull and the domain faces, level transitions on a face
// included): no misses up to the faces, single-valued (C0) on random cell values, and the field
// there constant along the face normal; and the build of the hierarchy handed over (its input
// freed block by block) identical to the build of the hierarchy kept. ctest runs 300 hierarchies;
// run `TestRandomHierarchies 10000` for the full sweep.
#include "mesh/DualMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace amrdm;

namespace
{
/// The boundary layer of `amr` with random cell values in [0, 1]: points within one coarse
/// cell of the domain faces (half of them on a face, edge or corner, or on a lattice plane of a
/// random level), each must be claimed, by primitives that agree (C0), and with the value it has
/// at the faces' point q (p with every coordinate closer than half a finest cell to a face moved
/// onto it: below the hull of the cell centres the field is constant along the normal). Returns
/// the misses; raises `spread` and `clamp` (absolute, the values' range is 1).
long checkBoundaryLayer(AmrHierarchy amr, std::mt19937& rng, double& spread, double& clamp)
{
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (AmrBlock& block : amr.blocks)
    for (float& v : block.values)
      v = value(rng);
  const DualMesh mesh = buildDualMesh(amr);
  const DualMeshView view = mesh.view();
  const GridBox box = amr.domainBox();
  const glm::dvec3 lo(box.lower), hi(box.upper);
  const double w0 = static_cast<double>(amr.levelWidth(0));
  const double half = 0.5 * static_cast<double>(amr.levelWidth(amr.numLevels() - 1));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long misses = 0;
  for (int i = 0; i < 400; ++i)
  {
    glm::dvec3 p = lo + glm::dvec3(u(rng), u(rng), u(rng)) * (hi - lo);
    const int axis = static_cast<int>(rng() % 3u);
    p[axis] = rng() % 2u ? lo[axis] + u(rng) * w0 : hi[axis] - u(rng) * w0;
    for (int d = 0; d < 3 && i % 2; ++d)
    {
      const int pick = static_cast<int>(rng() % 3u);
      const double w = static_cast<double>(
        amr.levelWidth(static_cast<int>(rng() % static_cast<unsigned>(amr.numLevels()))));
      if (pick == 0)
        p[d] = rng() % 2u ? lo[d] : hi[d]; // on a face
      else if (pick == 1)
        p[d] = glm::clamp((std::floor(p[d] / w - 0.5) + 0.5) * w, lo[d], hi[d]);
    }
    glm::dvec3 q = p;
    for (int d = 0; d < 3; ++d)
      q[d] = p[d] - lo[d] < half ? lo[d] : (hi[d] - p[d] < half ? hi[d] : p[d]);
    float values[16], atFace[16];
    std::uint32_t refs[16];
    const int hits = sampleFieldAllHits(view, glm::vec3(p), ElementTestParams{}, values, refs, 16);
    const int faceHits =
      sampleFieldAllHits(view, glm::vec3(q), ElementTestParams{}, atFace, refs, 16);
    if (hits == 0 || faceHits == 0)
    {
      ++misses;
      continue;
    }
    for (int k = 1; k < hits; ++k)
      spread = std::max(spread, double(std::abs(values[k] - values[0])));
    clamp = std::max(clamp, double(std::abs(values[0] - atFace[0])));
  }
  return misses;
}
} // namespace

/// The build of a hierarchy handed over (buildDualMesh(AmrHierarchy&&), which frees each block's
/// values and states during the gridlet fill once no later gridlet reads them) against `mesh`,
/// built from `amr` kept: the same gridlets, scalars (bit for bit), vertices and element indices,
/// and every block of the handed-over copy freed. Returns false (and says why) otherwise.
bool sameWhenHandedOver(const AmrHierarchy& amr, const DualMesh& mesh)
{
  AmrHierarchy copy = amr;
  const DualMesh moved = buildDualMesh(std::move(copy));
  const auto same = [](const auto& x, const auto& y)
  {
    return x.size() == y.size() &&
           (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  bool ok = same(mesh.gridlets, moved.gridlets) &&
            same(mesh.gridletScalars, moved.gridletScalars) && same(mesh.vertices, moved.vertices);
  for (int k = 0; k < kElementKindCount; ++k)
    ok = ok && same(mesh.elementIndices[k], moved.elementIndices[k]);
  if (!ok)
    std::printf("the build of the handed-over hierarchy differs from the build of the kept one\n");
  for (const AmrBlock& block : copy.blocks)
    if (!block.values.empty() || !block.state.empty())
    {
      std::printf("a block of the handed-over hierarchy still holds its values or states\n");
      return false;
    }
  return ok;
}

int main(int argc, char* argv[])
{
  const int count = argc > 1 ? std::atoi(argv[1]) : 300;
  /// The tolerance, relative to the field's range.
  constexpr double kRelativeTolerance = 1e-5;
  long points = 0, misses = 0, failures = 0;
  double worstLinear = 0.0, worstSpread = 0.0, worstClamp = 0.0;
  for (int h = 0; h < count; ++h)
  {
    std::mt19937 rng(static_cast<unsigned>(h));
    amrdm_test::SyntheticOptions opt;
    opt.levels = 1 + static_cast<int>(rng() % 6u);
    opt.rootCells = glm::ivec3(3 + rng() % 6u, 3 + rng() % 6u, 3 + rng() % 6u);
    opt.boxesPerLevel = 1 + static_cast<int>(rng() % 4u);
    opt.maxBoxCells = 2 + static_cast<int>(rng() % 4u);
    opt.splitRoot = rng() % 2u == 0;
    const glm::dvec3 a(std::uniform_real_distribution<double>(-1, 1)(rng),
      std::uniform_real_distribution<double>(-1, 1)(rng),
      std::uniform_real_distribution<double>(-1, 1)(rng));
    AmrHierarchy amr = amrdm_test::makeSynthetic(
      static_cast<unsigned>(h), opt, [&](const glm::dvec3& p) { return float(glm::dot(a, p)); });
    amr.finalizeCellStates();
    const DualMesh mesh = buildDualMesh(amr);
    const DualMeshView view = mesh.view();
    const double w0 = static_cast<double>(amr.levelWidth(0));
    const glm::dvec3 extent = glm::dvec3(opt.rootCells) * w0;
    const double range =
      std::abs(a.x) * extent.x + std::abs(a.y) * extent.y + std::abs(a.z) * extent.z;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    long localMisses = 0;
    double localLinear = 0.0, localSpread = 0.0, localClamp = 0.0;
    for (int i = 0; i < 1000; ++i)
    {
      glm::dvec3 p = w0 + glm::dvec3(u(rng), u(rng), u(rng)) * (extent - 2.0 * w0);
      if (i % 2)
      {
        // Snap one to three coordinates to a cell-centre plane of a random level.
        const double w =
          static_cast<double>(amr.levelWidth(static_cast<int>(rng() % unsigned(amr.numLevels()))));
        for (int d = 0; d < 1 + static_cast<int>(rng() % 3u); ++d)
          p[d] = glm::clamp((std::floor(p[d] / w - 0.5) + 0.5) * w, w0, extent[d] - w0);
      }
      float values[16];
      std::uint32_t refs[16];
      const int hits =
        sampleFieldAllHits(view, glm::vec3(p), ElementTestParams{}, values, refs, 16);
      ++points;
      if (hits == 0)
      {
        ++localMisses;
        continue;
      }
      localLinear =
        std::max(localLinear, std::abs(values[0] - glm::dot(a, glm::dvec3(glm::vec3(p)))) / range);
      for (int k = 1; k < hits; ++k)
        localSpread = std::max(localSpread, std::abs(double(values[k]) - values[0]) / range);
    }
    localMisses += checkBoundaryLayer(amr, rng, localSpread, localClamp);
    const bool handedOver = sameWhenHandedOver(amr, mesh);
    misses += localMisses;
    worstLinear = std::max(worstLinear, localLinear);
    worstSpread = std::max(worstSpread, localSpread);
    worstClamp = std::max(worstClamp, localClamp);
    if (localMisses > 0 || localLinear > kRelativeTolerance || localSpread > kRelativeTolerance ||
        localClamp > kRelativeTolerance || !handedOver)
    {
      ++failures;
      std::printf("hierarchy %d (levels %d): %ld misses, linear %.3g, spread %.3g, clamp %.3g\n",
        h,
        amr.numLevels(),
        localMisses,
        localLinear,
        localSpread,
        localClamp);
    }
  }
  std::printf("%d random hierarchies, %ld points: %ld misses, worst linear error / range %.3g, "
              "worst spread between claims / range %.3g, worst boundary-layer clamp error %.3g\n",
    count,
    points,
    misses,
    worstLinear,
    worstSpread,
    worstClamp);
  std::printf("%d passed, %ld failed\n", count - int(failures), failures);
  return failures == 0 ? 0 : 1;
}
