// The dual-mesh field on every real set: counts per element type, memory, build rate, linear
// reproduction (1e5 points) and watertight, single-valued sampling (1e6 points).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RealData.h"

#include "AMRDualMeshVTKCompat.h"
#include "vtkAMRDualMesh.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"

#include "mesh/DualMesh.h"
#include "sampling/FieldSampler.h"
#include "core/ParallelFor.h"

#include <chrono>
#include <cstdio>
#include <random>

namespace
{
constexpr double kRelativeTolerance = 1e-5;

/// Writes f = a . x + b (world coordinates of cell centres) as cell array "linear".
void addLinearField(vtkOverlappingAMR* amr, const double a[3], double b)
{
  for (unsigned l = 0; l < amrdm_vtk::amrcompat::NumberOfLevels(amr); ++l)
    for (unsigned i = 0; i < amrdm_vtk::amrcompat::NumberOfBlocks(amr, l); ++i)
    {
      vtkImageData* grid = amrdm_vtk::amrcompat::Block(amr, l, i);
      if (!grid)
        continue;
      vtkNew<vtkDoubleArray> f;
      f->SetName("linear");
      f->SetNumberOfTuples(grid->GetNumberOfCells());
      double o[3], h[3];
      int dims[3];
      grid->GetOrigin(o);
      grid->GetSpacing(h);
      grid->GetDimensions(dims);
      vtkIdType id = 0;
      for (int z = 0; z < dims[2] - 1; ++z)
        for (int y = 0; y < dims[1] - 1; ++y)
          for (int x = 0; x < dims[0] - 1; ++x)
          {
            const double c[3] = {
              o[0] + (x + 0.5) * h[0], o[1] + (y + 0.5) * h[1], o[2] + (z + 0.5) * h[2]
            };
            f->SetValue(id++, a[0] * c[0] + a[1] * c[1] + a[2] * c[2] + b);
          }
      grid->GetCellData()->AddArray(f);
    }
}

/// Level-0 bounding box in world coordinates, shrunk by one coarsest cell.
void innerDomain(vtkOverlappingAMR* amr, double lo[3], double hi[3])
{
  double h[3];
  amrdm_vtk::amrcompat::Spacing(amr, 0, h);
  for (int d = 0; d < 3; ++d)
  {
    lo[d] = 1e300;
    hi[d] = -1e300;
  }
  for (unsigned i = 0; i < amrdm_vtk::amrcompat::NumberOfBlocks(amr, 0); ++i)
  {
    double b[6];
    amrdm_vtk::amrcompat::Block(amr, 0, i)->GetBounds(b);
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], b[2 * d]);
      hi[d] = std::max(hi[d], b[2 * d + 1]);
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    lo[d] += h[d];
    hi[d] -= h[d];
  }
}
} // namespace

TEST_CASE("real sets: counts, memory, linear reproduction, watertightness")
{
  int tested = 0;
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
  {
    if (set.path.empty())
    {
      MESSAGE("skipping ", set.name, ": not found (large sets live in ../shared/amr-data)");
      continue;
    }
    ++tested;
    vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
    REQUIRE(amr);
    double lo[3], hi[3];
    innerDomain(amr, lo, hi);
    const double a[3] = { 1.0 / (hi[0] - lo[0]), -0.6 / (hi[1] - lo[1]), 0.35 / (hi[2] - lo[2]) };
    addLinearField(amr, a, 2.0);
    const double range = std::abs(a[0]) * (hi[0] - lo[0]) + std::abs(a[1]) * (hi[1] - lo[1]) +
                         std::abs(a[2]) * (hi[2] - lo[2]);

    vtkNew<vtkAMRDualMesh> field;
    field->SetInputData(amr);
    field->SetNumberOfThreads(2);
    field->SetArrayName("linear");
    REQUIRE(field->Update());
    const amrdm::DualMesh& mesh = *field->GetDualMesh();
    const double rate = double(field->GetNumberOfLeafCells()) / field->GetBuildSeconds();
    std::printf(
      "%s: levels %u, leaf cells %lld, gridlets %lld, perfect cubes %lld, tets %lld, "
      "pyramids %lld, wedges %lld, hexes %lld (degenerate %lld), vertices %lld\n"
      "  memory %.2f B/leaf cell (%s)\n  built in %.3f s on 2 threads (AMR intake %.3f s): "
      "%.2f M leaf cells/s\n",
      set.name.c_str(),
      amrdm_vtk::amrcompat::NumberOfLevels(amr),
      (long long)field->GetNumberOfLeafCells(),
      (long long)field->GetNumberOfGridlets(),
      (long long)field->GetNumberOfPerfectCubes(),
      (long long)field->GetNumberOfTets(),
      (long long)field->GetNumberOfPyramids(),
      (long long)field->GetNumberOfWedges(),
      (long long)field->GetNumberOfHexes(),
      (long long)field->GetNumberOfDegenerateHexes(),
      (long long)field->GetNumberOfStitchingVertices(),
      field->GetBytesPerLeafCell(),
      mesh.memoryReport().toJson().c_str(),
      field->GetBuildSeconds(),
      field->GetIntakeSeconds(),
      rate * 1e-6);

    // Linear reproduction: 1e5 random points.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int misses = 0;
    double worst = 0.0;
    for (int i = 0; i < 100000; ++i)
    {
      const double x = lo[0] + u(rng) * (hi[0] - lo[0]), y = lo[1] + u(rng) * (hi[1] - lo[1]),
                   z = lo[2] + u(rng) * (hi[2] - lo[2]);
      const double v = field->Sample(x, y, z);
      if (std::isnan(v))
      {
        ++misses;
        continue;
      }
      worst = std::max(worst, std::abs(v - (a[0] * x + a[1] * y + a[2] * z + 2.0)) / range);
    }
    std::printf("  linear: 1e5 points, %d misses, worst error / range %.3g\n", misses, worst);
    CHECK(misses == 0);
    CHECK(worst <= kRelativeTolerance);

    // Watertight and single-valued on the real array: 1e6 points, every claim compared.
    field->SetArrayName(set.array.c_str());
    REQUIRE(field->Update());
    const amrdm::DualMesh& real = *field->GetDualMesh();
    const amrdm::DualMeshView view = real.view();
    float vmin = 1e30f, vmax = -1e30f;
    for (float s : real.gridletScalars)
      if (s == s)
      {
        vmin = std::min(vmin, s);
        vmax = std::max(vmax, s);
      }
    for (const amrdm::ElementVertex& v : real.vertices)
    {
      vmin = std::min(vmin, v.value);
      vmax = std::max(vmax, v.value);
    }
    const double valueRange = std::max(1e-30, double(vmax) - double(vmin));
    constexpr int kChunks = 64, kPerChunk = 1000000 / kChunks;
    std::vector<int> chunkMisses(kChunks, 0), chunkMulti(kChunks, 0);
    std::vector<double> chunkSpread(kChunks, 0.0);
    amrdm::parallelFor(kChunks,
      2,
      [&](std::size_t c)
      {
        std::mt19937 crng(static_cast<unsigned>(1000 + c));
        std::uniform_real_distribution<double> cu(0.0, 1.0);
        for (int i = 0; i < kPerChunk; ++i)
        {
          const glm::dvec3 x(lo[0] + cu(crng) * (hi[0] - lo[0]),
            lo[1] + cu(crng) * (hi[1] - lo[1]),
            lo[2] + cu(crng) * (hi[2] - lo[2]));
          const glm::dvec3 g = real.gridFromWorld(x);
          float values[16];
          std::uint32_t refs[16];
          const int hits =
            amrdm::sampleFieldAllHits(view, g, amrdm::ElementTestParams{}, values, refs, 16);
          chunkMisses[c] += hits == 0;
          chunkMulti[c] += hits > 1;
          for (int h = 1; h < hits; ++h)
            chunkSpread[c] =
              std::max(chunkSpread[c], std::abs(double(values[h]) - values[0]) / valueRange);
        }
      });
    int wMisses = 0, wMulti = 0;
    double spread = 0.0;
    for (int c = 0; c < kChunks; ++c)
    {
      wMisses += chunkMisses[c];
      wMulti += chunkMulti[c];
      spread = std::max(spread, chunkSpread[c]);
    }
    std::printf("  watertight (%s): 1e6 points, %d misses, %d claimed twice or more, worst "
                "spread / range %.3g\n",
      set.array.c_str(),
      wMisses,
      wMulti,
      spread);
    CHECK(wMisses == 0);
    CHECK(spread <= kRelativeTolerance);
    CHECK(field->GetBuildCount() == 2);
  }
  CHECK(tested >= 3);
}
