// vtkAMRDualMeshProbeFilter in a C++ pipeline (the Python test covers SetSourceData): the Enzo
// reader connected as the source, probe values equal to vtkAMRDualMesh::Sample, points outside
// the domain masked, new points without a rebuild, another array with one, an unknown array
// failing with an error and the filter recovering afterwards. It is also the probe filter's leak
// check: Testing/Robustness/Sanitizers runs it under AddressSanitizer/LeakSanitizer.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "RealData.h"

#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshProbeFilter.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

namespace
{
/// Checks every probed point against vtkAMRDualMesh::Sample; returns {inside, masked}.
std::pair<int, int> checkAgainstSample(vtkAMRDualMeshProbeFilter* probe, const char* array)
{
  vtkDataSet* out = vtkDataSet::SafeDownCast(probe->GetOutputDataObject(0));
  REQUIRE(out);
  vtkDataArray* values = out->GetPointData()->GetArray(array);
  vtkDataArray* mask = out->GetPointData()->GetArray("vtkValidPointMask");
  REQUIRE(values);
  REQUIRE(mask);
  CHECK(values->GetDataType() == VTK_FLOAT);
  CHECK(mask->GetDataType() == VTK_CHAR);
  CHECK(std::string(out->GetPointData()->GetScalars()->GetName()) == array);
  vtkAMRDualMesh* field = probe->GetDualMesh();
  int inside = 0, masked = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double direct = field->Sample(x[0], x[1], x[2]);
    if (mask->GetTuple1(i) != 0)
    {
      ++inside;
      REQUIRE(std::abs(values->GetTuple1(i) - direct) <= 1e-6 * std::abs(direct));
    }
    else
    {
      ++masked;
      REQUIRE(std::isnan(direct));
    }
    if (x[0] > 1.0) // the Enzo domain is the unit cube
    {
      REQUIRE(mask->GetTuple1(i) == 0);
    }
  }
  return { inside, masked };
}
}

TEST_CASE("probe filter fed by a reader through the pipeline")
{
  const amrdm_test::RealSet enzo = amrdm_test::realSets()[0];
  REQUIRE(enzo.name == "enzo-moving7");
  REQUIRE_FALSE(enzo.path.empty());
  vtkNew<vtkAMREnzoReader> reader;
  reader->SetFileName(enzo.path.c_str());
  reader->UpdateInformation();
  reader->SetMaxLevel(1000);
  reader->GetCellDataArraySelection()->EnableAllArrays();

  // 16^3 points, x from 0.03 to 1.23: a fifth of them lie outside the domain.
  vtkNew<vtkImageData> points;
  points->SetDimensions(16, 16, 16);
  points->SetOrigin(0.03, 0.03, 0.03);
  points->SetSpacing(0.08, 0.06, 0.06);

  vtkNew<vtkAMRDualMeshProbeFilter> probe;
  probe->SetInputData(points);
  probe->SetSourceConnection(reader->GetOutputPort());
  probe->SetArrayName("Density");
  probe->SetNumberOfThreads(2);
  int errors = 0;
  vtkNew<vtkCallbackCommand> countErrors;
  countErrors->SetClientData(&errors);
  countErrors->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  probe->AddObserver(vtkCommand::ErrorEvent, countErrors);
  probe->GetDualMesh()->AddObserver(vtkCommand::ErrorEvent, countErrors);

  REQUIRE(probe->GetExecutive()->Update() == 1);
  CHECK(errors == 0);
  auto [inside, masked] = checkAgainstSample(probe, "Density");
  MESSAGE("Density: ", inside, " points inside, ", masked, " masked");
  CHECK(inside > 0);
  CHECK(masked >= 16 * 16 * 3); // x = 1.03, 1.11, 1.19 at least
  const int builds = probe->GetDualMesh()->GetBuildCount();
  CHECK(builds == 1);

  SUBCASE("new points reuse the dual mesh, another array rebuilds it")
  {
    points->SetOrigin(0.05, 0.04, 0.02);
    REQUIRE(probe->GetExecutive()->Update() == 1);
    CHECK(probe->GetDualMesh()->GetBuildCount() == builds);
    checkAgainstSample(probe, "Density");

    probe->SetArrayName("Temperature");
    REQUIRE(probe->GetExecutive()->Update() == 1);
    CHECK(probe->GetDualMesh()->GetBuildCount() == builds + 1);
    std::tie(inside, masked) = checkAgainstSample(probe, "Temperature");
    CHECK(inside > 0);
    CHECK(errors == 0);
  }

  SUBCASE("an unknown array fails with an error, a valid one recovers")
  {
    probe->SetArrayName("NoSuchArray");
    CHECK(probe->GetExecutive()->Update() == 0);
    CHECK(errors >= 2); // the dual mesh's message and the probe filter's
    probe->SetArrayName("Density");
    const int before = errors;
    REQUIRE(probe->GetExecutive()->Update() == 1);
    CHECK(errors == before);
    checkAgainstSample(probe, "Density");
  }
}
