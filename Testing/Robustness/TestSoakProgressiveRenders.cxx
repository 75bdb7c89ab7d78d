// Soak: many progressive renders of vtkAMRDualMeshVolumeMapper in one process with random
// changes between them: the camera (orbit, zoom, projection), the volume property (colour and
// opacity points, unit distance, shading), the mapper (integrator, samples per render, step,
// samples per cell, majorant resolution, threads, seed) and the input (the Enzo set, the flame
// set, or a new random synthetic hierarchy). Resident memory (/proc/self/statm) after the
// warm-up (the first fifth of the renders, when every kind of change has happened) must not
// grow by more than 1 % by the end, and nothing may crash.
// Usage: TestSoakProgressiveRenders [RENDERS] (ctest runs 300; RENDERS = 2000 for the full soak).
#include "vtkAMRDualMeshVolumeMapper.h"

#include "RealData.h"

#include "vtkAMRBox.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUniformGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <unistd.h>
#include <vector>

namespace
{
double residentMiB()
{
  long pages = 0, resident = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r"))
  {
    if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2)
      resident = 0;
    std::fclose(f);
  }
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

/// A random two-level hierarchy over [0, 1]^3 with array "f" (a smooth blob).
vtkSmartPointer<vtkOverlappingAMR> randomHierarchy(std::mt19937& rng)
{
  auto uni = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const int n = uni(6, 14);
  const int size = uni(1, n / 2), lo0[3] = { uni(0, n - size), uni(0, n - size), uni(0, n - size) };
  const int blocks[2] = { 1, 1 };
  auto amr = vtkSmartPointer<vtkOverlappingAMR>::New();
  amr->Initialize(2, blocks);
  const double origin[3] = { 0, 0, 0 };
  amr->SetOrigin(origin);
  for (unsigned l = 0; l < 2; ++l)
  {
    const double h = 1.0 / n / (1 << l);
    const double spacing[3] = { h, h, h };
    amr->SetSpacing(l, spacing);
    amr->SetRefinementRatio(l, 2);
    int lo[3], hi[3];
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = l == 0 ? 0 : 2 * lo0[d];
      hi[d] = l == 0 ? n - 1 : 2 * (lo0[d] + size) - 1;
    }
    amr->SetAMRBox(l, 0, vtkAMRBox(lo, hi));
    vtkNew<vtkUniformGrid> grid;
    grid->SetDimensions(hi[0] - lo[0] + 2, hi[1] - lo[1] + 2, hi[2] - lo[2] + 2);
    grid->SetSpacing(h, h, h);
    grid->SetOrigin(lo[0] * h, lo[1] * h, lo[2] * h);
    vtkNew<vtkDoubleArray> f;
    f->SetName("f");
    f->SetNumberOfTuples(grid->GetNumberOfCells());
    const int nx = hi[0] - lo[0] + 1, ny = hi[1] - lo[1] + 1;
    for (vtkIdType c = 0; c < f->GetNumberOfTuples(); ++c)
    {
      const double x = (lo[0] + c % nx + 0.5) * h - 0.5, y = (lo[1] + c / nx % ny + 0.5) * h - 0.5,
                   z = (lo[2] + c / (vtkIdType(nx) * ny) + 0.5) * h - 0.5;
      f->SetValue(c, std::exp(-8.0 * (x * x + y * y + z * z)));
    }
    grid->GetCellData()->AddArray(f);
    amr->SetDataSet(l, 0, grid);
  }
  return amr;
}

struct Input
{
  vtkSmartPointer<vtkOverlappingAMR> amr;
  const char* array;
  double range[2];
};
}

int main(int argc, char* argv[])
{
  const int renders = argc > 1 ? std::atoi(argv[1]) : 300;
  constexpr double kMaxGrowth = 0.01;
  std::vector<Input> inputs;
  for (const amrdm_test::RealSet& set : amrdm_test::realSets())
  {
    if ((set.name == "enzo-moving7" || set.name == "amrex-flame3d") && !set.path.empty())
    {
      Input in{ amrdm_test::readSet(set), set.enzo ? "Density" : "temp", { 0, 0 } };
      // Enzo density is in g/cm^3 (1e-28 .. 1e-21): a linear ramp over its low end.
      in.range[0] = set.enzo ? 0.0 : 300.0;
      in.range[1] = set.enzo ? 1e-25 : 1600.0;
      inputs.push_back(in);
    }
  }
  if (inputs.empty())
  {
    std::printf("SKIP: the Enzo and flame sets (Testing/Data) are missing\n");
    return 125;
  }
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  vtkNew<vtkAMRDualMeshVolumeMapper> mapper;
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(48, 40);
  window->AddRenderer(ren);

  Input current = inputs[0];
  auto setInput = [&](const Input& in)
  {
    current = in;
    mapper->SetInputData(in.amr);
    mapper->SelectScalarArray(in.array);
    ren->ResetCamera();
  };
  auto setProperty = [&]
  {
    const double lo = current.range[0], hi = current.range[1];
    color->RemoveAllPoints();
    opacity->RemoveAllPoints();
    const int points = 2 + int(rng() % 4u);
    for (int p = 0; p < points; ++p)
    {
      const double x = lo + (hi - lo) * double(p) / (points - 1);
      color->AddRGBPoint(x, u(rng), u(rng), u(rng));
      opacity->AddPoint(x, p == 0 ? 0.0 : u(rng));
    }
    property->SetScalarOpacityUnitDistance(0.01 + 0.2 * u(rng));
    property->SetShade(rng() % 2u);
  };
  setInput(current);
  setProperty();
  double baseline = 0.0, peak = 0.0;
  int inputChanges = 0, propertyChanges = 0, cameraChanges = 0, mapperChanges = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < renders; ++i)
  {
    const unsigned what = rng() % 100u;
    if (what < 4)
    {
      ++inputChanges;
      if (rng() % 2u)
        setInput(Input{ randomHierarchy(rng), "f", { 0.0, 1.0 } });
      else
        setInput(inputs[rng() % inputs.size()]);
      setProperty();
    }
    else if (what < 30)
    {
      ++propertyChanges;
      setProperty();
    }
    else if (what < 65)
    {
      ++cameraChanges;
      vtkCamera* cam = ren->GetActiveCamera();
      cam->Azimuth(360.0 * u(rng));
      cam->Elevation(60.0 * u(rng) - 30.0);
      cam->OrthogonalizeViewUp();
      cam->SetParallelProjection(rng() % 4u == 0);
      ren->ResetCamera();
      cam->Zoom(0.7 + u(rng));
    }
    else if (what < 80)
    {
      ++mapperChanges;
      mapper->SetIntegrator(int(rng() % 5u));
      mapper->SetSamplesPerRender(1 + int(rng() % 3u));
      mapper->SetMaximumSamples(1 + int(rng() % 16u));
      mapper->SetStepSize(rng() % 2u ? 0.0 : 0.01 + 0.05 * u(rng));
      mapper->SetSamplesPerCell(rng() % 2u ? 0.0 : 0.5 + u(rng));
      mapper->SetMajorantResolution(rng() % 2u ? 0 : 1 + int(rng() % 16u));
      mapper->SetNumberOfThreads(1 + int(rng() % 2u));
      mapper->SetSeed(int(rng() % 1000u));
    }
    window->Render(); // otherwise: accumulate (progressive)
    const double rss = residentMiB();
    if (i + 1 == renders / 5)
      baseline = rss;
    peak = std::max(peak, rss);
  }
  const double end = residentMiB();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double growth = baseline > 0 ? (end - baseline) / baseline : 0.0;
  std::printf("%d renders in %.1f s (%d input, %d property, %d camera, %d mapper changes); "
              "resident memory %.1f MiB after %d renders, %.1f MiB at the end (%+.2f %%), peak "
              "%.1f MiB\n",
    renders,
    seconds,
    inputChanges,
    propertyChanges,
    cameraChanges,
    mapperChanges,
    baseline,
    renders / 5,
    end,
    100.0 * growth,
    peak);
  if (!(baseline > 0.0) || growth > kMaxGrowth)
  {
    std::printf("FAIL: resident memory grew by %.2f %% (limit %.0f %%)\n",
      100.0 * growth,
      100.0 * kMaxGrowth);
    return 1;
  }
  std::printf(
    "ok: resident memory growth %.2f %% <= %.0f %%\n", 100.0 * growth, 100.0 * kMaxGrowth);
  return 0;
}
