// Property test over many random, properly nested hierarchies (levels 1..6, ratio 2, touching
// and nested boxes): linear reproduction and watertightness (no misses, every claiming
// primitive agrees) at random and lattice-aligned points. ctest runs 300 hierarchies; run
// `TestRandomHierarchies 10000` for the full sweep.
#include "mesh/DualMeshBuilder.h"
#include "sampling/FieldSampler.h"
#include "SyntheticAmr.h"

#include <cstdio>
#include <cstdlib>
#include <random>

using namespace amrdm;

int main(int argc, char* argv[])
{
  const int count = argc > 1 ? std::atoi(argv[1]) : 300;
  /// The tolerance, relative to the field's range.
  constexpr double kRelativeTolerance = 1e-5;
  long points = 0, misses = 0, failures = 0;
  double worstLinear = 0.0, worstSpread = 0.0;
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
    double localLinear = 0.0, localSpread = 0.0;
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
    misses += localMisses;
    worstLinear = std::max(worstLinear, localLinear);
    worstSpread = std::max(worstSpread, localSpread);
    if (localMisses > 0 || localLinear > kRelativeTolerance || localSpread > kRelativeTolerance)
    {
      ++failures;
      std::printf("hierarchy %d (levels %d): %ld misses, linear %.3g, spread %.3g\n",
        h,
        amr.numLevels(),
        localMisses,
        localLinear,
        localSpread);
    }
  }
  std::printf("%d random hierarchies, %ld points: %ld misses, worst linear error / range %.3g, "
              "worst spread between claims / range %.3g\n",
    count,
    points,
    misses,
    worstLinear,
    worstSpread);
  std::printf("%d passed, %ld failed\n", count - int(failures), failures);
  return failures == 0 ? 0 : 1;
}
