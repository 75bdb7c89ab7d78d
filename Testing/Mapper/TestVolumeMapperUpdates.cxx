// What vtkAMRDualMeshVolumeMapper recomputes, and when (real data: AMReX advection, phi):
// - a transfer-function-only change (opacity points) changes the image but does not rebuild the
//   dual mesh (vtkAMRDualMesh::GetBuildCount), and resets the accumulation;
// - Render() adds SamplesPerRender samples until MaximumSamples, then only re-composites;
//   RenderUntil() stops exactly at the requested count;
// - a camera change, a light change, a clipping-plane change, a window resize and a mapper
//   parameter change each reset the accumulation; a Render() with nothing changed does not;
// - level-adaptive ray marching (SamplesPerCell) resets and renders the uniform step's picture;
// - a clipping plane that removes the whole volume leaves only the background;
// - progress events are forwarded while building; ReleaseGraphicsResources() followed by a
//   render works; PrintSelf prints every parameter.
#include "VolumeMapperScene.h"

#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace
{
int failures = 0;
void check(bool ok, const char* what)
{
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what);
  failures += ok ? 0 : 1;
}

/// Mean absolute difference of two RGB pixel buffers, 0..255.
double meanDiff(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  double sum = 0.0;
  const vtkIdType n = a->GetNumberOfValues();
  for (vtkIdType i = 0; i < n; ++i)
  {
    sum += std::abs(int(a->GetValue(i)) - int(b->GetValue(i)));
  }
  return n > 0 ? sum / n : 0.0;
}

void grab(vtkRenderWindow* w, vtkUnsignedCharArray* out)
{
  const int* size = w->GetSize();
  w->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, out);
}
}

int main(int, char*[])
{
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_test::readAdvection();
  if (!amr)
  {
    std::printf("SKIP: the AMReX advection set is missing\n");
    return 125;
  }
  vtkNew<vtkAMRDualMeshVolumeMapper> mapper;
  mapper->SetInputData(amr);
  mapper->SelectScalarArray("phi");
  mapper->SetIntegrator(vtkAMRDualMeshVolumeMapper::RAY_MARCH);
  mapper->SetStepSize(0.004);
  mapper->SetMaximumSamples(3);
  int progressEvents = 0;
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&progressEvents);
  progress->SetCallback(
    [](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<int*>(cd); });
  mapper->AddObserver(vtkCommand::ProgressEvent, progress);

  vtkSmartPointer<vtkVolumeProperty> property = amrdm_test::advectionProperty();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(120, 100);
  window->AddRenderer(ren);
  amrdm_test::advectionCamera(ren);
  double bounds[6];
  mapper->GetBounds(bounds);
  check(bounds[0] == 0.0 && bounds[1] == 1.0 && bounds[5] == 0.25, "GetBounds() from the AMR");

  window->Render();
  check(mapper->GetDualMesh()->GetBuildCount() == 1, "first render builds the dual mesh once");
  check(progressEvents > 0, "progress events forwarded while building");
  check(mapper->GetNumberOfSamples() == 1, "one render adds SamplesPerRender = 1 sample");
  window->Render();
  check(mapper->GetNumberOfSamples() == 2, "a render with nothing changed accumulates");
  check(mapper->RenderUntil(window, 10) == 3, "RenderUntil stops at MaximumSamples = 3");
  window->Render();
  check(mapper->GetNumberOfSamples() == 3, "at MaximumSamples a render only re-composites");
  vtkNew<vtkUnsignedCharArray> before, after;
  grab(window, before);

  // Transfer function only: the opacity function changes.
  property->GetScalarOpacity()->AddPoint(1.1, 0.6);
  window->Render();
  check(mapper->GetDualMesh()->GetBuildCount() == 1, "opacity change: dual mesh not rebuilt");
  check(mapper->GetNumberOfSamples() == 1, "opacity change: accumulation reset");
  mapper->RenderUntil(window, 3);
  grab(window, after);
  const double tfDiff = meanDiff(before, after);
  std::printf("mean |difference| after the opacity change: %.2f / 255\n", tfDiff);
  check(tfDiff > 1.0, "opacity change: the image changes");
  // Colour only.
  property->GetRGBTransferFunction()->AddRGBPoint(1.4, 0.0, 1.0, 0.0);
  window->Render();
  check(mapper->GetDualMesh()->GetBuildCount() == 1 && mapper->GetNumberOfSamples() == 1,
    "colour change: no rebuild, accumulation reset");

  auto resets = [&](const char* what, auto&& change)
  {
    mapper->RenderUntil(window, 3);
    change();
    window->Render();
    check(mapper->GetNumberOfSamples() == 1, what);
  };
  resets("camera change resets", [&] { ren->GetActiveCamera()->Azimuth(10.0); });
  resets("light change resets",
    [&]
    {
      vtkNew<vtkLight> light;
      light->SetPosition(1.0, 1.0, 1.0);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      ren->AddLight(light);
    });
  resets("clipping plane change resets",
    [&] { mapper->SetClippingPlanes(amrdm_test::advectionPlanes()); });
  resets("moving a clipping plane resets",
    [&]
    {
      vtkPlane::SafeDownCast(mapper->GetClippingPlanes()->GetItemAsObject(0))
        ->SetOrigin(0.7, 0.5, 0.5);
    });
  resets("window resize resets", [&] { window->SetSize(100, 100); });
  resets("mapper parameter change resets", [&] { mapper->SetStepSize(0.005); });
  {
    // Level-adaptive ray marching: a reset, and the same picture as the uniform step (the
    // advection set has two levels; most of the slab is coarse).
    mapper->SetStepSize(0.002);
    mapper->RenderUntil(window, 3);
    vtkNew<vtkUnsignedCharArray> uniform, adaptive;
    grab(window, uniform);
    resets("samples-per-cell change resets", [&] { mapper->SetSamplesPerCell(2.0); });
    mapper->RenderUntil(window, 3);
    grab(window, adaptive);
    double sum = 0.0;
    int worst = 0;
    for (vtkIdType i = 0; i < uniform->GetNumberOfValues(); ++i)
    {
      const int d = std::abs(int(uniform->GetValue(i)) - int(adaptive->GetValue(i)));
      sum += d;
      worst = std::max(worst, d);
    }
    const double mean = sum / double(std::max<vtkIdType>(1, uniform->GetNumberOfValues()));
    std::printf(
      "adaptive (2 samples per cell) vs uniform step 0.002: mean |d| %.3f, max %d of 255\n",
      mean,
      worst);
    check(mean < 1.0 && worst < 24, "the adaptive step renders the picture of the uniform step");
    mapper->SetSamplesPerCell(0.0);
    mapper->SetStepSize(0.005);
  }
  resets("shade change resets", [&] { property->ShadeOn(); });
  check(mapper->GetDualMesh()->GetBuildCount() == 1, "none of these rebuilt the dual mesh");
  mapper->SetGridletSize(4);
  window->Render();
  check(mapper->GetDualMesh()->GetBuildCount() == 2, "gridlet size change rebuilds");

  // A plane that keeps only z > 1 (above the slab) leaves nothing: the window is background.
  {
    vtkNew<vtkPlaneCollection> above;
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(0.0, 0.0, 1.0);
    plane->SetNormal(0.0, 0.0, 1.0);
    above->AddItem(plane);
    mapper->SetClippingPlanes(above);
    window->Render();
    vtkNew<vtkUnsignedCharArray> clipped;
    grab(window, clipped);
    int maxValue = 0;
    for (vtkIdType i = 0; i < clipped->GetNumberOfValues(); ++i)
    {
      maxValue = std::max(maxValue, int(clipped->GetValue(i)));
    }
    check(maxValue == 0, "a clipping plane that removes everything leaves the background");
    mapper->RemoveAllClippingPlanes();
  }

  mapper->ReleaseGraphicsResources(window);
  window->Render();
  check(mapper->GetNumberOfSamples() >= 1, "render after ReleaseGraphicsResources");

  std::ostringstream os;
  mapper->Print(os);
  for (const char* name : { "Integrator",
         "ElementTest",
         "MaxNewtonIterations",
         "GridletSize",
         "SamplesPerRender",
         "MaximumSamples",
         "MaximumBounces",
         "ScatteringAnisotropy",
         "StepSize",
         "SamplesPerCell",
         "MajorantResolution",
         "NumberOfThreads",
         "Seed",
         "EnvironmentRadiance" })
  {
    if (os.str().find(std::string(name) + ":") == std::string::npos)
    {
      std::printf("PrintSelf misses %s\n", name);
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
