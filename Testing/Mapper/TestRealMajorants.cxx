// Majorants on every real set: at 10^6 random points per set and transfer function, the
// extinction the renderer samples never exceeds its macrocell's majorant.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RealData.h"

#include "vtkAMRDualMesh.h"

#include "sampling/FieldSampler.h"
#include "accel/MajorantGrid.h"
#include "core/ParallelFor.h"
#include "sampling/TransferFunction.h"

#include <algorithm>
#include <cstdio>
#include <random>

namespace
{
/// Transfer functions that stress the majorant: a ramp, a narrow spike, a random table.
std::vector<amrdm::TransferFunction> transferFunctions(double lo, double hi, std::mt19937& rng)
{
  std::vector<amrdm::TransferFunction> tfs(3);
  const double span = hi - lo;
  for (auto& tf : tfs)
  {
    tf.lo = float(lo);
    tf.hi = float(hi);
    tf.unitDistance = float(0.01 * span > 0 ? 0.05 : 1.0);
    tf.table.assign(128, glm::vec4(1.0f, 1.0f, 1.0f, 0.0f));
  }
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 128; ++i)
  {
    tfs[0].table[i].w = float(i) / 127.0f;
    tfs[1].table[i].w = (i == 77) ? 0.95f : 0.0f;
    tfs[2].table[i].w = u(rng) * u(rng);
  }
  return tfs;
}
}

TEST_CASE("no sampled extinction exceeds its majorant on the real sets")
{
  int tested = 0;
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
  {
    if (set.path.empty())
    {
      MESSAGE("skipping ", set.name, ": not found");
      continue;
    }
    ++tested;
    vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
    vtkNew<vtkAMRDualMesh> field;
    field->SetInputData(amr);
    field->SetArrayName(set.array.c_str());
    field->SetLogScale(set.enzo); // Enzo density spans decades
    REQUIRE(field->Update());
    const amrdm::DualMesh& mesh = *field->GetDualMesh();
    const amrdm::DualMeshView view = mesh.view();
    amrdm::MajorantGrid grid = amrdm::buildMajorantRanges(mesh);
    // The automatic resolution follows the data: at most 16 B per kDefaultLeafCellsPerMacrocell
    // leaf cells (0.25 B per leaf cell), or the small floor; no floor dominates the deep Enzo set.
    const double budget =
      16.0 * std::max(double(amrdm::kDefaultMinMacrocells),
               double(mesh.counts.leafCells) / double(amrdm::kDefaultLeafCellsPerMacrocell));
    // 16 B per macrocell once the majorants are filled (range, cell width, majorant).
    const double bytes = 16.0 * double(grid.res.x) * double(grid.res.y) * double(grid.res.z);
    std::printf("%s: automatic majorant grid %dx%dx%d, %.3f B per leaf cell\n",
      set.name.c_str(),
      grid.res.x,
      grid.res.y,
      grid.res.z,
      bytes / double(mesh.counts.leafCells));
    CHECK(bytes <= budget);
    std::mt19937 rng(5);
    int tfIndex = 0;
    for (const amrdm::TransferFunction& tf :
      transferFunctions(field->GetValueRange()[0], field->GetValueRange()[1], rng))
    {
      amrdm::updateMajorants(grid, tf.view());
      const amrdm::MajorantGridView gv = grid.view();
      const amrdm::TransferFunctionView tv = tf.view();
      constexpr int kChunks = 32, kPerChunk = 1000000 / kChunks;
      std::vector<long> violations(kChunks, 0), dense(kChunks, 0);
      std::vector<double> tightness(kChunks, 0.0);
      amrdm::parallelFor(kChunks,
        2,
        [&](std::size_t c)
        {
          std::mt19937 crng(static_cast<unsigned>(c * 7919 + tfIndex));
          std::uniform_real_distribution<float> u(0.0f, 1.0f);
          for (int i = 0; i < kPerChunk; ++i)
          {
            const glm::vec3 p = gv.lo + glm::vec3(u(crng), u(crng), u(crng)) * (gv.hi - gv.lo);
            const glm::vec3 g((glm::dvec3(p) - mesh.origin) / mesh.finestSpacing);
            float value;
            if (!amrdm::sampleField(view, g, amrdm::ElementTestParams{}, value))
              continue;
            const float sigma = amrdm::tfExtinction(tv, value);
            const float majorant = amrdm::majorantAt(gv, p);
            violations[c] += sigma > majorant;
            if (sigma > 0.0f)
            {
              ++dense[c];
              tightness[c] += sigma / majorant;
            }
          }
        });
      long v = 0, d = 0;
      double t = 0.0;
      for (int c = 0; c < kChunks; ++c)
      {
        v += violations[c];
        d += dense[c];
        t += tightness[c];
      }
      std::printf("%s, transfer function %d: 1e6 points, %ld violations, mean sigma/majorant "
                  "%.3f where sigma > 0 (grid %dx%dx%d)\n",
        set.name.c_str(),
        tfIndex,
        v,
        d ? t / d : 0.0,
        grid.res.x,
        grid.res.y,
        grid.res.z);
      CHECK(v == 0);
      ++tfIndex;
    }
  }
  CHECK(tested >= 3);
}
