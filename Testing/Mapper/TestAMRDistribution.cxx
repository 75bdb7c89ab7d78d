// Data-parallel rendering's data side without MPI (Mapper/AMRDualMeshDistribution.h): the AMR
// is dealt to N simulated ranks round-robin (as vtkAMRBaseReader does), each rank packs the
// pieces every region needs, every region assembles its own vtkOverlappingAMR from what all
// ranks sent, and its dual mesh must equal the serial one inside the region, sample for sample
// (random points of each region; NaN where the serial mesh has no value). Also: the regions
// tile the domain, the same on every call; a region no rank sent anything to is empty. The
// proxy (DistributionMode Proxy) gathered from every rank is level 0, one level, with level 0's
// mean, or fewer averaged cells within a cell budget.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RealData.h"

#include "AMRDualMeshDistribution.h"
#include "AMRDualMeshProxy.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkAMRBox.h"
#include "vtkAMRDualMesh.h"
#include "vtkUniformGrid.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{
/// `amr`'s metadata with the data of the blocks whose flat index is `rank` modulo `ranks`.
vtkSmartPointer<vtkOverlappingAMR> dealt(vtkOverlappingAMR* amr, int rank, int ranks)
{
  const unsigned levels = amr->GetNumberOfLevels();
  std::vector<int> blocks(levels);
  for (unsigned l = 0; l < levels; ++l)
  {
    blocks[l] = static_cast<int>(amr->GetNumberOfDataSets(l));
  }
  auto out = vtkSmartPointer<vtkOverlappingAMR>::New();
  out->Initialize(static_cast<int>(levels), blocks.data());
  out->SetOrigin(amr->GetOrigin());
  int flat = 0;
  for (unsigned l = 0; l < levels; ++l)
  {
    double h[3];
    amr->GetSpacing(l, h);
    out->SetSpacing(l, h);
    for (unsigned id = 0; id < amr->GetNumberOfDataSets(l); ++id, ++flat)
    {
      out->SetAMRBox(l, id, amr->GetAMRBox(l, id));
      if (flat % ranks == rank)
      {
        out->SetDataSet(l, id, amr->GetDataSet(l, id));
      }
    }
  }
  return out;
}

void checkSet(const amrdm_test::RealSet& set, int ranks)
{
  CAPTURE(set.name);
  CAPTURE(ranks);
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
  REQUIRE(amr);
  vtkNew<vtkAMRDualMesh> serial;
  serial->SetInputData(amr);
  serial->SetArrayName(set.array.c_str());
  serial->SetNumberOfThreads(1);
  REQUIRE(serial->Update());

  std::vector<vtkSmartPointer<vtkOverlappingAMR>> local;
  amrdm_vtk::AMRPartition partition;
  std::string error;
  for (int q = 0; q < ranks; ++q)
  {
    local.push_back(dealt(amr, q, ranks));
  }
  REQUIRE_MESSAGE(amrdm_vtk::PartitionAMR(local[0], ranks, partition, error), error);
  REQUIRE(partition.Regions.size() == std::size_t(ranks));
  double volume = 0.0;
  for (const auto& r : partition.Regions)
  {
    volume += (r[1] - r[0]) * (r[3] - r[2]) * (r[5] - r[4]);
  }
  const auto& d = partition.Domain;
  CHECK(volume == doctest::Approx((d[1] - d[0]) * (d[3] - d[2]) * (d[5] - d[4])));

  std::mt19937 rng(12345);
  for (int r = 0; r < ranks; ++r)
  {
    std::vector<std::vector<char>> received(static_cast<std::size_t>(ranks));
    for (int q = 0; q < ranks; ++q)
    {
      amrdm_vtk::AMRPartition mine;
      REQUIRE(amrdm_vtk::PartitionAMR(local[q], ranks, mine, error));
      REQUIRE(mine.Regions == partition.Regions); // the same tree on every rank
      REQUIRE_MESSAGE(
        amrdm_vtk::PackRegionPieces(local[q], mine, r, false, received[q], error), error);
    }
    vtkSmartPointer<vtkOverlappingAMR> region = amrdm_vtk::AssembleRegion(amr, received, error);
    REQUIRE_MESSAGE(region, error);
    vtkNew<vtkAMRDualMesh> mesh;
    mesh->SetInputData(region);
    mesh->SetArrayName(set.array.c_str());
    mesh->SetNumberOfThreads(1);
    REQUIRE(mesh->Update());
    const auto& b = partition.Regions[static_cast<std::size_t>(r)];
    int compared = 0, mismatches = 0;
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i)
    {
      double p[3];
      for (int a = 0; a < 3; ++a)
      {
        p[a] = std::uniform_real_distribution<double>(b[2 * a], b[2 * a + 1])(rng);
      }
      const double want = serial->Sample(p[0], p[1], p[2]);
      const double got = mesh->Sample(p[0], p[1], p[2]);
      if (std::isnan(want) || std::isnan(got))
      {
        mismatches += std::isnan(want) != std::isnan(got) ? 1 : 0;
        continue;
      }
      ++compared;
      const double err = std::abs(want - got) / std::max(1.0, std::abs(want));
      worst = std::max(worst, err);
      mismatches += err > 1e-5 ? 1 : 0;
    }
    CAPTURE(r);
    CAPTURE(worst);
    CHECK(compared > 1000);
    CHECK(mismatches == 0);
  }
}
}

TEST_CASE("regions' dual meshes equal the serial one inside each region")
{
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
  {
    if (set.path.empty() || set.name == "amrex-singlevortex-6.7M")
    {
      continue;
    }
    for (int ranks : { 2, 3, 4 })
    {
      checkSet(set, ranks);
    }
  }
}

TEST_CASE("a region that receives nothing is an empty AMR; a malformed buffer is refused")
{
  const amrdm_test::RealSet set = amrdm_test::realSets()[0];
  if (set.path.empty())
  {
    return;
  }
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
  std::string error;
  vtkSmartPointer<vtkOverlappingAMR> empty =
    amrdm_vtk::AssembleRegion(amr, std::vector<std::vector<char>>(3), error);
  REQUIRE(empty);
  CHECK(empty->GetNumberOfLevels() == 0);
  std::vector<std::vector<char>> bad(1, std::vector<char>(7, 'x'));
  CHECK(!amrdm_vtk::AssembleRegion(amr, bad, error));
  CHECK(error.find("malformed") != std::string::npos);
  amrdm_vtk::AMRPartition p;
  CHECK(!amrdm_vtk::PartitionAMR(amr, 1 << 30, p, error));
  CHECK(error.find("level-0 cells") != std::string::npos);
}

TEST_CASE("the proxy: level 0 of every rank, one level, averaged down to a cell budget")
{
  const amrdm_test::RealSet set = amrdm_test::realSets()[2]; // advection: 3 levels
  CAPTURE(set.name);
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readSet(set);
  REQUIRE(amr);
  const int ranks = 3;
  std::vector<std::vector<char>> buffers(ranks);
  std::string error;
  long long level0 = 0;
  double sum0 = 0.0;
  for (unsigned id = 0; id < amr->GetNumberOfDataSets(0); ++id)
  {
    vtkDataArray* a = amr->GetDataSet(0, id)->GetCellData()->GetArray(set.array.c_str());
    level0 += a->GetNumberOfTuples();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      sum0 += a->GetComponent(i, 0);
    }
  }
  for (int q = 0; q < ranks; ++q)
  {
    REQUIRE_MESSAGE(amrdm_vtk::PackCoarseBlocks(dealt(amr, q, ranks), buffers[q], error), error);
  }
  // No budget pressure: level 0 itself; a budget of an eighth or less: averaged 2^3 (or more).
  for (long long budget : { level0, level0 / 8, level0 / 60 })
  {
    CAPTURE(budget);
    vtkSmartPointer<vtkOverlappingAMR> proxy =
      amrdm_vtk::AssembleCoarse(amr, buffers, budget, error);
    REQUIRE_MESSAGE(proxy, error);
    REQUIRE(proxy->GetNumberOfLevels() == 1);
    long long cells = 0;
    double sum = 0.0;
    for (unsigned id = 0; id < proxy->GetNumberOfDataSets(0); ++id)
    {
      vtkDataArray* a = proxy->GetDataSet(0, id)->GetCellData()->GetArray(set.array.c_str());
      REQUIRE(a);
      cells += a->GetNumberOfTuples();
      for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      {
        sum += a->GetComponent(i, 0);
      }
    }
    CHECK(cells <= budget);
    CHECK(cells * 64 > budget); // the smallest coarsening that fits (factor 2 per step)
    // Level 0 covers the domain: the mean is kept.
    CHECK(sum / double(cells) == doctest::Approx(sum0 / double(level0)).epsilon(1e-9));
    vtkNew<vtkAMRDualMesh> mesh;
    mesh->SetInputData(proxy);
    mesh->SetArrayName(set.array.c_str());
    REQUIRE(mesh->Update());
    CHECK(mesh->GetNumberOfLeafCells() == cells);
  }
  std::vector<std::vector<char>> bad{ std::vector<char>(5, 'x') };
  CHECK(!amrdm_vtk::AssembleCoarse(amr, bad, level0, error));
  CHECK(!error.empty());
}
